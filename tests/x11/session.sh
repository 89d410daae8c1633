# tests/x11/session.sh — what the window tests (tests/window*.sh) share,
# sourced by them from the top folder: the counters and `finish`, a private
# Xvfb (start_x: if it cannot start, the test fails, it never skips), a vroc
# session reading a pipe, waits, the window's id, a drag.  (Here, not in
# tests/: tests/run.sh runs every tests/*.sh as a suite.)
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

# ---- the X server: a private Xvfb on the first free display :91..:99 -------
start_x() {
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
}

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
# wait_count FILE PATTERN N: up to 10 s for N lines that match
wait_count() {
    i=0
    while [ $i -lt 100 ]; do [ "$(grep -c "$2" "$1" 2>/dev/null)" -ge "$3" ] && return 0; sleep 0.1; i=$((i + 1)); done
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

# drag_right ID: press at (320,256), 10 x 8 pixels every 20 ms, the release
# at once after the last (a throw, not a stop and a drop)
drag_right() {
    moves="mousemove --window $1 320 256 sleep 0.1 mousedown 1"
    x=320
    for k in 1 2 3 4 5 6 7 8 9 10; do x=$((x + 8)); moves="$moves sleep 0.02 mousemove --window $1 $x 256"; done
    # shellcheck disable=SC2086
    xdotool $moves mouseup 1
}
# retry CMD...: CMD until it succeeds, up to 5 s (the X server and the
# window's service take their time on a loaded machine)
retry() {
    i=0
    while [ $i -lt 25 ]; do "$@" && return 0; sleep 0.2; i=$((i + 1)); done
    return 1
}
