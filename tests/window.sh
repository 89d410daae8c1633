#!/bin/sh
# tests/window.sh — the live window (SPEC 9) under Xvfb, driven by xdotool,
# seen by tests/x11/xshot (the window's pixels as the X server holds them):
#   the window shows the frame's pixels (the screenshot is the frame file)
#   a drag turns the view as the trackball formula says, and `save` keeps it
#   the prompt (a pipe) answers while the window runs; space runs time
#   see_through from its key; side and anaglyph compose the eyes
#   the mouse as the hand: picks the ball, moves on the plane facing the
#   view, throws with the drag's velocity
#   no $DISPLAY: a clear error
# Xvfb is started here; if it cannot be, every test fails (no skip).
# Ends with `N passed, M failed`.
set -u
top=$(pwd)
case ${VROC_BUILD:?set VROC_BUILD to the build folder} in
/*) build=$VROC_BUILD ;;
*) build=$top/$VROC_BUILD ;;
esac
vroc=$build/vroc xshot=$build/tests/xshot
passed=0 failed=0
tmp=$(mktemp -d)
xpid=
cleanup() {
    [ -n "$xpid" ] && kill "$xpid" 2>/dev/null
    [ -n "${KEEP:-}" ] || rm -rf "$tmp"
}
trap cleanup EXIT
pass() { passed=$((passed + 1)); }
fail() { echo "FAIL $*"; failed=$((failed + 1)); }
finish() { echo "$passed passed, $failed failed"; [ "$failed" = 0 ]; exit $?; }
export LSAN_OPTIONS="suppressions=$top/tests/lsan.supp:print_suppressions=0"

# ---- no display: a clear error, status 1 ------------------------------------
printf 'window\n' | env -u DISPLAY "$vroc" >"$tmp/nd.out" 2>"$tmp/nd.err"
st=$?
if [ "$st" = 1 ] && grep -q '^vroc: <stdin>:1: window: \$DISPLAY is not set' "$tmp/nd.err"; then pass
else fail "no DISPLAY: status $st, stderr: $(cat "$tmp/nd.err")"; fi

# ---- the X server -----------------------------------------------------------
for t in Xvfb xdotool; do
    command -v $t >/dev/null || { fail "window: $t is not installed (make deps)"; finish; }
done
[ -x "$xshot" ] || { fail "window: no $xshot"; finish; }
for n in 91 92 93 94 95 96 97 98 99; do
    [ -e "/tmp/.X$n-lock" ] && continue
    Xvfb ":$n" -screen 0 1600x1200x24 -nolisten tcp >"$tmp/xvfb.log" 2>&1 &
    xpid=$!
    i=0
    while [ $i -lt 50 ] && ! [ -e "/tmp/.X11-unix/X$n" ]; do sleep 0.1; i=$((i + 1)); done
    if [ -e "/tmp/.X11-unix/X$n" ] && kill -0 "$xpid" 2>/dev/null; then export DISPLAY=":$n"; break; fi
    kill "$xpid" 2>/dev/null; xpid=
done
[ -n "$xpid" ] || { fail "window: cannot start Xvfb: $(tail -n 3 "$tmp/xvfb.log")"; finish; }

# ---- a session: vroc reading a pipe (batch mode) ----------------------------
# open_session: vroc < $tmp/in (a FIFO held open on fd 3), out and err files
open_session() {
    rm -f "$tmp/in"; mkfifo "$tmp/in"
    (cd "$tmp" && exec env VROC_HAND_LOG="$tmp/hand.log" timeout 120 "$vroc" <"$tmp/in" >"$tmp/out" 2>"$tmp/err") &
    vpid=$!
    exec 3>"$tmp/in"
}
say() { printf '%s\n' "$@" >&3; }
close_session() { exec 3>&-; wait "$vpid"; }
# wait_for FILE PATTERN: up to 10 s
wait_for() {
    i=0
    while [ $i -lt 100 ]; do grep -q "$2" "$1" 2>/dev/null && return 0; sleep 0.1; i=$((i + 1)); done
    return 1
}
# the window's id once it is shown
window_id() {
    i=0
    while [ $i -lt 100 ]; do
        id=$(xdotool search --name '^vroc$' 2>/dev/null | head -n 1)
        [ -n "$id" ] && { echo "$id"; return 0; }
        sleep 0.1; i=$((i + 1))
    done
    return 1
}
# bytes that differ between two equal-sized PPMs
differ() { cmp -l "$1" "$2" 2>/dev/null | wc -l; }

scene='sphere red
color = (255,0,0)
radius = 0.5
ures = 24
vres = 24
translate = (1.5,0,1)
cube blue
color = (0,0,255)
size = (0.4,0.4,0.4)
translate = (-1.5,0,1)'

# ---- 1. the window shows the frame: the screenshot is the frame file --------
open_session
say "$scene" "ipd = 0" "frames = f1" window "dump"
if wait_for "$tmp/out" '^blue,' && id=$(window_id); then
    sleep 0.3
    "$xshot" "$id" "$tmp/shot1.ppm"
    if cmp -s "$tmp/shot1.ppm" "$tmp/f1/frame-000000-left.ppm"; then pass
    else fail "window: the screenshot is not the frame ($(differ "$tmp/shot1.ppm" "$tmp/f1/frame-000000-left.ppm") bytes differ)"; fi
else fail "window: no window or no answer: $(cat "$tmp/err")"; id=; fi

# ---- 2. a drag of 128 pixels to the right turns the scene pi/4 about the ---
# screen's up u = (0,2,8)/sqrt(68) (which stays): eye - look = (0,-8,2),
# normal to u, turns to (-sqrt(68) s, -8 c, 2 c)
if [ -n "$id" ]; then
    xdotool mousemove --window "$id" 300 256 mousedown 1 sleep 0.05 mousemove --window "$id" 364 256 \
        sleep 0.05 mousemove --window "$id" 428 256 sleep 0.05 mouseup 1
    sleep 0.3
    say "frames = f2" refresh "save drag.vroc" "dump"
    wait_for "$tmp/out" '^blue,.*$' && sleep 0.5
    eye=$(awk 'BEGIN { t = atan2(1, 1); printf "(%.17g,%.17g,%.17g)", -sqrt(68) * sin(t), -8 * cos(t), 1 + 2 * cos(t) }')
    (cd "$tmp" && printf '%s\nipd = 0\neye = %s\nup = (0,2,8)\nframes = f3\nrefresh\n' "$scene" "$eye" | "$vroc" 2>"$tmp/ref.err")
    moved=$(differ "$tmp/f1/frame-000000-left.ppm" "$tmp/f2/frame-000000-left.ppm")
    off=$(differ "$tmp/f2/frame-000000-left.ppm" "$tmp/f3/frame-000000-left.ppm")
    # the formula's view and the dragged one: the same image but for a few
    # edge pixels (the eye agrees to rounding, 1e-15 m)
    if [ "$moved" -gt 10000 ] && [ "$off" -lt 200 ]; then pass
    else fail "trackball: drag changed $moved bytes, differs from the formula's view in $off"; fi
    # the dragged view is the settings' eye, look and up (not the window's
    # own): `save` holds it, and a fresh vroc reading the save draws the
    # same frame (SPEC 11)
    (cd "$tmp" && printf 'read drag.vroc\nframes = f4\nrefresh\n' | "$vroc" 2>"$tmp/drag.err")
    if [ ! -s "$tmp/drag.err" ] && cmp -s "$tmp/f2/frame-000000-left.ppm" "$tmp/f4/frame-000000-left.ppm"; then pass
    else fail "trackball: the saved view draws another frame: $(head -c 200 "$tmp/drag.err")"; fi
fi

# ---- 3. the prompt answers while the window runs; space runs time ----------
if [ -n "$id" ]; then
    say gravity
    sleep 0.2
    xdotool key --window "$id" space
    sleep 1.5
    xdotool key --window "$id" space
    say "stats"
    if wait_for "$tmp/out" '^frames=' || wait_for "$tmp/out" 'frames='; then
        fr=$(grep -o 'frames=[0-9]*' "$tmp/out" | tail -n 1 | cut -d= -f2)
        # 1.5 s of real time at time_step 0.1: about 15 frames
        if [ "${fr:-0}" -ge 8 ] && [ "${fr:-0}" -le 25 ]; then pass
        else fail "space key: $fr frames in 1.5 s of real time (expected about 15)"; fi
    else fail "prompt: no answer to stats while the window runs"; fi
fi
close_session
grep -q . "$tmp/err" && { fail "session 1 wrote errors:"; sed 's/^/    /' "$tmp/err" | head -n 5; }

# ---- 4. side by side and anaglyph; see_through from the key ----------------
open_session
say "$scene" "real = 1" "window_mode = side" "frames = f4" window dump
if wait_for "$tmp/out" '^blue,' && id=$(window_id); then
    sleep 0.3
    "$xshot" "$id" "$tmp/side.ppm"
    # the window is the two frame files side by side
    w=$(head -n 2 "$tmp/side.ppm" | tail -n 1)
    if [ "$w" = "1280 512" ] && pamcut -left 0 -width 640 "$tmp/side.ppm" | cmp -s - "$tmp/f4/frame-000000-left.ppm" &&
        pamcut -left 640 -width 640 "$tmp/side.ppm" | cmp -s - "$tmp/f4/frame-000000-right.ppm"; then pass
    else fail "side: window $w is not left | right"; fi
    say "window_mode = anaglyph" refresh dump
    sleep 0.6
    "$xshot" "$id" "$tmp/ana.ppm"
    # anaglyph: red of the left eye, green and blue of the right
    red_ok=$(pamchannel -infile "$tmp/ana.ppm" 0 | cmp -s - "$(pamchannel -infile "$tmp/f4/frame-000000-left.ppm" 0 >"$tmp/l0.pam"; echo "$tmp/l0.pam")" && echo 1)
    blue_ok=$(pamchannel -infile "$tmp/ana.ppm" 2 | cmp -s - "$(pamchannel -infile "$tmp/f4/frame-000000-right.ppm" 2 >"$tmp/r2.pam"; echo "$tmp/r2.pam")" && echo 1)
    if [ "$red_ok" = 1 ] && [ "$blue_ok" = 1 ]; then pass
    else fail "anaglyph: red from the left eye $red_ok, blue from the right $blue_ok"; fi
    # see_through: t twice = 2, the real cube (blue) is not drawn
    say "window_mode = mono"
    sleep 0.3
    xdotool key --window "$id" t sleep 0.1 key --window "$id" t
    sleep 0.5
    "$xshot" "$id" "$tmp/st.ppm"
    blue=$(pamchannel -infile "$tmp/st.ppm" 2 | pamsumm -max -brief 2>/dev/null)
    red=$(pamchannel -infile "$tmp/st.ppm" 0 | pamsumm -max -brief 2>/dev/null)
    if [ "${blue:-1}" = 0 ] && [ "${red:-0}" -gt 200 ]; then pass
    else fail "see_through key: max blue $blue (want 0), max red $red"; fi
else fail "side: no window: $(cat "$tmp/err")"; fi
close_session

# ---- 5. the mouse as the hand -------------------------------------------------
# The ball at look, the pointer at its centre (320,256): the pick meets its
# front at distance t from the eye; then 10 steps of 8 pixels every 20 ms to
# the right.  On the plane through the grabbed point facing the view a pixel
# is 2 t tan(22.5 deg) / 512 m, along r = (1,0,0): the hand moves 80 pixels'
# worth in x only, and the throw is 8 pixels / 20 ms of it.
open_session
say "sphere ball" "radius = 0.5" "ures = 24" "vres = 24" "translate = (0,0,1)" window dump
if wait_for "$tmp/out" '^ball,' && id=$(window_id); then
    sleep 0.3
    moves="mousemove --window $id 320 256 sleep 0.1 key --window $id g sleep 0.1 mousedown 1 sleep 0.05"
    x=320
    for k in 1 2 3 4 5 6 7 8 9 10; do x=$((x + 8)); moves="$moves mousemove --window $id $x 256 sleep 0.02"; done
    # shellcheck disable=SC2086
    xdotool $moves mouseup 1
    sleep 0.3
    say dump
    sleep 0.3
    if awk -v out="$tmp/hand.awk" '
        /^# grab / { grab = $3 }
        /^[0-9.]+ hand / { n++; if (n == 1) { x0 = $3; y0 = $4; z0 = $5 } x1 = $3; y1 = $4; z1 = $5; last = $NF }
        /^# throw / { vx = $3; vy = $4; vz = $5; thrown = 1 }
        END {
            t = sqrt(x0 * x0 + (y0 + 8) ^ 2 + (z0 - 3) ^ 2)       # from the eye (0,-8,3)
            r = sqrt(x0 * x0 + y0 * y0 + (z0 - 1) ^ 2)            # from the ball centre
            px = 2 * t * 0.41421356237 / 512
            want = 80 * px; vwant = 8 * px / 0.02
            bad = ""
            if (grab != "ball") bad = bad " grabbed [" grab "]"
            if (r < 0.49 || r > 0.501) bad = bad " grab point " r " m from the centre"
            if ((x1 - x0) < 0.97 * want || (x1 - x0) > 1.03 * want) bad = bad " moved " (x1 - x0) " m, want " want
            if ((y1 - y0) ^ 2 + (z1 - z0) ^ 2 > 1e-6) bad = bad " left the plane"
            if (!thrown || last != 0) bad = bad " no release"
            if (vx < 0.6 * vwant || vx > 1.4 * vwant || vy * vy + vz * vz > 0.01 * vwant * vwant)
                bad = bad " throw (" vx "," vy "," vz ") want (" vwant ",0,0)"
            print bad > out
            exit bad != ""
        }' "$tmp/hand.log"; then pass
    else fail "hand:$(cat "$tmp/hand.awk")"; sed 's/^/    /' "$tmp/hand.log" | head -n 20; fi
else fail "hand: no window: $(cat "$tmp/err")"; fi
close_session
finish
