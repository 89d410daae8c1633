#!/bin/sh
# tests/window.sh — the live window (SPEC 9) under Xvfb, driven by xdotool,
# seen by tests/x11/xshot (the window's pixels as the X server holds them):
#   the window shows the frame's pixels (the screenshot is the frame file)
#   a drag turns the view as the trackball formula says, and `save` keeps it
#   the prompt (a pipe) answers while the window runs; space runs time
#   see_through from its key; side and anaglyph compose the eyes
#   the mouse as the hand: picks the ball, pushes the hand's samples into
#   the world on the plane facing the view (show hand), stopped and running,
#   throws with the drag's velocity
#   resize: the window keeps the user's size, every mode drawn for it
#   no $DISPLAY: a clear error
# Xvfb is started here; if it cannot be, every test fails (no skip).
# Ends with `N passed, M failed`.
set -u
top=$(pwd)
. "$top/tests/x11/session.sh"

# ---- no display: a clear error, status 1 ------------------------------------
printf 'window\n' | env -u DISPLAY "$vroc" >"$tmp/nd.out" 2>"$tmp/nd.err"
st=$?
if [ "$st" = 1 ] && grep -q '^vroc: <stdin>:1: window: \$DISPLAY is not set' "$tmp/nd.err"; then pass
else fail "no DISPLAY: status $st, stderr: $(cat "$tmp/nd.err")"; fi

# ---- the X server -----------------------------------------------------------
start_x

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
    say gravity "max_linear = 100"   # they fall 1.5 s, past 8 m/s: no cap, and so no note on stderr
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
    # the window is the two frame files side by side (drawn by the time
    # the screenshot is taken: retried, as a loaded machine may be late)
    side4_ok() {
        "$xshot" "$id" "$tmp/side.ppm" && w=$(head -n 2 "$tmp/side.ppm" | tail -n 1) && [ "$w" = "1280 512" ] &&
            pamcut -left 0 -width 640 "$tmp/side.ppm" | cmp -s - "$tmp/f4/frame-000000-left.ppm" &&
            pamcut -left 640 -width 640 "$tmp/side.ppm" | cmp -s - "$tmp/f4/frame-000000-right.ppm"
    }
    if retry side4_ok; then pass
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

# ---- 5. the mouse as the hand ------------------------------------------------
# The ball at look, the pointer at its centre (320,256): the pick meets its
# front, the trigger goes down there; then 10 steps of 8 pixels every 20 ms
# to the right, the release.  The hand point moves on the plane through the
# grabbed point p0 facing the view (forward f = (0,8,-2)/sqrt 68 from the
# eye (0,-8,3)): the pointer ray o + s d at the last pixel, s = f.(p0-o)/f.d
# (the view's pixel rays: vrView_PointerRay, fov 45, 640x512).
# (a) time stopped: every sample falls at the end of the frame to come
#     (0.1), the last one winning; after `step`, `show hand` is the drag's
#     end, trigger up; the release has no velocity (the drag took no time).
# (b) time running (space): the samples' times follow the wall clock, never
#     decrease; the throw is the drag's velocity along +x: 80 pixels' worth
#     over the drag's wall time (loose: xdotool's pace on a loaded machine;
#     tests/test_hand.c checks the exact figure), and the hand runs on
#     50 ms at it (the sample vrTrack's velocity at the release is taken from).
hand_end() { # hand_end LOGFILE N: the formula's hand point, N-th grab, pixel 400
    awk -v g="$2" '
        /^# grab / { n++ }
        /^[0-9.e+-]+ hand / && n == g && !got { x0 = $3; y0 = $4; z0 = $5; got = 1 }
        END {
            t = atan2(1, 1) / 2; t = sin(t) / cos(t)
            fx = 0; fy = 8 / sqrt(68); fz = -2 / sqrt(68)
            rx = 1; ry = 0; rz = 0
            ux = ry * fz - rz * fy; uy = rz * fx - rx * fz; uz = rx * fy - ry * fx
            sx = (2 * 400.5 / 640 - 1) * t * 640 / 512; sy = (1 - 2 * 256.5 / 512) * t
            dx = fx + sx * rx + sy * ux; dy = fy + sx * ry + sy * uy; dz = fz + sx * rz + sy * uz
            l = sqrt(dx * dx + dy * dy + dz * dz); dx /= l; dy /= l; dz /= l
            s = (fx * x0 + fy * (y0 + 8) + fz * (z0 - 3)) / (fx * dx + fy * dy + fz * dz)
            printf "%.17g %.17g %.17g\n", s * dx, -8 + s * dy, 3 + s * dz
        }' "$1"
}
open_session
say "sphere ball" "radius = 0.5" "ures = 24" "vres = 24" "translate = (0,0,1)" window dump
if wait_for "$tmp/out" '^ball,' && id=$(window_id); then
    sleep 0.3
    xdotool key --window "$id" g
    sleep 0.1
    drag_right "$id"
    sleep 0.3
    say step "show hand" dump       # dump: a batch run's stdout is written out at a dump
    wait_count "$tmp/out" '^ball,' 2
    want=$(hand_end "$tmp/hand.log" 1)
    if awk -v want="$want" -v out="$tmp/hand.awk" '
        FNR == NR { if ($1 == "hand") shown = $0; next }
        /^# grab / { grab = $3 }
        /^[0-9.e+-]+ hand / { n++; if (n == 1) { first = $NF; x0 = $3; y0 = $4; z0 = $5 } last = $NF
                              if ($1 != 0.1) bad = bad " sample at " $1 " (want 0.1)"
                              if (n > 1 && n < 12 && $NF != 1) bad = bad " trigger up mid-drag" }
        /^# throw / { v = $3 " " $4 " " $5 }
        END {
            split(want, w, " "); split(shown, h, " ")
            r = sqrt(x0 * x0 + y0 * y0 + (z0 - 1) ^ 2)
            if (grab != "ball") bad = bad " grabbed [" grab "]"
            if (r < 0.49 || r > 0.501) bad = bad " grab point " r " m from the centre"
            if (first != 1 || last != 0 || n != 12) bad = bad " trigger " first ".." last " in " n " samples"
            if (v != "0 0 0") bad = bad " throw " v " while stopped"
            if (h[2] != 0.1 || h[10] != 0 || h[6] != 1) bad = bad " show hand [" shown "]"
            for (i = 1; i <= 3; i++) if ((h[2 + i] - w[i]) ^ 2 > 1e-18) bad = bad " show hand " i ": " h[2 + i] " want " w[i]
            print bad > out
            exit bad != ""
        }' "$tmp/out" "$tmp/hand.log"; then pass
    else fail "hand, stopped:$(cat "$tmp/hand.awk")"; sed 's/^/    /' "$tmp/hand.log" | head -n 14; fi
    # (b) running
    xdotool key --window "$id" space
    sleep 0.3
    t0=$(date +%s.%N)
    drag_right "$id"
    t1=$(date +%s.%N)
    sleep 0.3
    xdotool key --window "$id" space
    sleep 0.2
    say "show hand" dump
    wait_count "$tmp/out" '^ball,' 3
    if awk -v wall="$(awk -v a="$t0" -v b="$t1" 'BEGIN { print b - a - 0.1 }')" -v out="$tmp/hand.awk" '
        FNR == NR { if ($1 == "hand") shown = $0; next }
        /^# grab / { g++ }
        /^[0-9.e+-]+ hand / { if (prev != "" && $1 < prev) bad = bad " time " $1 " after " prev; prev = $1 }
        /^[0-9.e+-]+ hand / && g == 2 { n++; if (n == 1) { first = $NF; t0 = $1; x0 = $3 } 
                                        if (n > 1 && $NF == 0 && !up) { up = 1; tu = $1; xu = $3; yu = $4; zu = $5; nu = n }
                                        if (up && n == nu + 1) { tr = $1; xr = $3; yr = $4; zr = $5 } }
        /^# throw / && g == 2 { vx = $3; vy = $4; vz = $5 }
        END {
            split(shown, h, " ")
            vwant = (xu - x0) / wall
            if (first != 1 || !up) bad = bad " trigger " first ", up " up
            if (t0 <= 0.1) bad = bad " pressed at " t0 " (time ran from 0.1)"
            if (tu - t0 < 0.5 * wall || tu - t0 > 1.5 * wall) bad = bad " drag took " (tu - t0) " s of time in " wall " s"
            if (vx < 0.4 * vwant || vx > 2 * vwant || vy * vy + vz * vz > 1e-4 * vx * vx)
                bad = bad " throw (" vx "," vy "," vz ") want about (" vwant ",0,0)"
            if ((tr - tu - 0.05) ^ 2 > 1e-20 || (xr - xu - 0.05 * vx) ^ 2 > 1e-18 || (yr - yu - 0.05 * vy) ^ 2 > 1e-18 ||
                (zr - zu - 0.05 * vz) ^ 2 > 1e-18) bad = bad " run-on sample " tr " " xr " after " tu " " xu
            if (h[2] <= tr || (h[3] - xr) ^ 2 > 1e-18 || h[10] != 0) bad = bad " show hand [" shown "]"
            print bad > out
            exit bad != ""
        }' "$tmp/out" "$tmp/hand.log"; then pass
    else fail "hand, running:$(cat "$tmp/hand.awk")"; sed 's/^/    /' "$tmp/hand.log" | tail -n 16; fi
else fail "hand: no window: $(cat "$tmp/err")"; fi
close_session
grep -q . "$tmp/err" && { fail "session 5 wrote errors:"; sed 's/^/    /' "$tmp/err" | head -n 5; }

# ---- 6. resize: the window keeps the user's size, drawn for it -------------
# xdotool windowsize 800x300: the screenshot is 800x300 and is the frame
# file of resolution (800,300) (nothing stretched: the view's fov is
# vertical, the width shows more); side by side each eye gets 400x300,
# anaglyph 800x300; a drag of 150 pixels (half the new height) turns the
# view a quarter turn (test 2's formula at pi/2), not 150/512 of a half.
open_session
say "$scene" "ipd = 0" window dump
if wait_for "$tmp/out" '^blue,' && id=$(window_id); then
    sleep 0.3
    xdotool windowsize "$id" 800 300
    (cd "$tmp" && printf '%s\nipd = 0\nresolution = (800,300)\nframes = f6\nrefresh\nipd = 0.064\nresolution = (400,300)\nframes = f6s\nrefresh\nresolution = (800,300)\nframes = f6a\nrefresh\n' "$scene" | "$vroc" 2>"$tmp/ref6.err")
    big_ok() { "$xshot" "$id" "$tmp/big.ppm" && cmp -s "$tmp/big.ppm" "$tmp/f6/frame-000000-left.ppm"; }
    retry big_ok
    size=$(head -n 2 "$tmp/big.ppm" | tail -n 1)
    red=$(pamchannel -infile "$tmp/big.ppm" 0 | pamsumm -max -brief 2>/dev/null)
    blue=$(pamchannel -infile "$tmp/big.ppm" 2 | pamsumm -max -brief 2>/dev/null)
    if [ "$size" = "800 300" ] && [ "${red:-0}" -gt 200 ] && [ "${blue:-0}" -gt 200 ] &&
        cmp -s "$tmp/big.ppm" "$tmp/f6/frame-000000-left.ppm"; then pass
    else fail "resize: window $size, max red $red, blue $blue, the frame at 800x300: $(differ "$tmp/big.ppm" "$tmp/f6/frame-000000-left.ppm") bytes differ"; fi
    say "ipd = 0.064" "window_mode = side" refresh dump
    side_ok() {
        "$xshot" "$id" "$tmp/bigside.ppm" && size=$(head -n 2 "$tmp/bigside.ppm" | tail -n 1) && [ "$size" = "800 300" ] &&
            pamcut -left 0 -width 400 "$tmp/bigside.ppm" | cmp -s - "$tmp/f6s/frame-000000-left.ppm" &&
            pamcut -left 400 -width 400 "$tmp/bigside.ppm" | cmp -s - "$tmp/f6s/frame-000000-right.ppm"
    }
    if retry side_ok; then pass
    else fail "resize, side: window $size is not left | right at 400x300 each"; fi
    say "window_mode = anaglyph" refresh dump
    pamchannel -infile "$tmp/f6a/frame-000000-left.ppm" 0 >"$tmp/l6.pam"
    pamchannel -infile "$tmp/f6a/frame-000000-right.ppm" 2 >"$tmp/r6.pam"
    ana_ok() {
        "$xshot" "$id" "$tmp/bigana.ppm" || return 1
        red_ok=$(pamchannel -infile "$tmp/bigana.ppm" 0 | cmp -s - "$tmp/l6.pam" && echo 1)
        blue_ok=$(pamchannel -infile "$tmp/bigana.ppm" 2 | cmp -s - "$tmp/r6.pam" && echo 1)
        [ "$red_ok" = 1 ] && [ "$blue_ok" = 1 ]
    }
    if retry ana_ok; then pass
    else fail "resize, anaglyph at 800x300: red from the left eye $red_ok, blue from the right $blue_ok"; fi
    say "window_mode = mono" "ipd = 0" refresh
    sleep 0.3
    xdotool mousemove --window "$id" 300 150 mousedown 1 sleep 0.05 mousemove --window "$id" 375 150 \
        sleep 0.05 mousemove --window "$id" 450 150 sleep 0.05 mouseup 1
    sleep 0.3
    say "frames = f7" refresh dump
    sleep 0.8
    eye=$(awk 'BEGIN { t = 2 * atan2(1, 1); printf "(%.17g,%.17g,%.17g)", -sqrt(68) * sin(t), -8 * cos(t), 1 + 2 * cos(t) }')
    (cd "$tmp" && printf '%s\nipd = 0\neye = %s\nup = (0,2,8)\nframes = f8\nrefresh\n' "$scene" "$eye" | "$vroc" 2>>"$tmp/ref6.err")
    off=$(differ "$tmp/f7/frame-000000-left.ppm" "$tmp/f8/frame-000000-left.ppm")
    if [ -s "$tmp/f7/frame-000000-left.ppm" ] && [ "$off" -lt 200 ]; then pass
    else fail "resize, trackball: 150 pixels of a 300-pixel window differ from a quarter turn in $off bytes"; fi
else fail "resize: no window: $(cat "$tmp/err")"; fi
close_session
grep -q . "$tmp/err" && { fail "session 6 wrote errors:"; sed 's/^/    /' "$tmp/err" | head -n 5; }
finish
