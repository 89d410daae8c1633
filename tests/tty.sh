#!/bin/sh
# tests/tty.sh — vroc at a terminal: drives it on a pseudo-terminal with
# tests/shell/ptydrive.c (built here with cc) and checks the banner and
# prompt, TAB completion, the history file, that errors keep the session,
# Ctrl-C (on a line, a long step and a running start), Ctrl-D (one prompt),
# exit, -i, and that `start` runs frames in real time while the prompt
# answers and `stop` halts them.  Every wait has a timeout; a setup that
# cannot run is a failure, not a skip.  Ends with `N passed, M failed`.
set -u
top=$(pwd)
case ${VROC_BUILD:?set VROC_BUILD to the build folder} in
/*) build=$VROC_BUILD ;;
*) build=$top/$VROC_BUILD ;;
esac
vroc=$build/vroc
passed=0 failed=0
tmp=$(mktemp -d)
trap '[ -n "${KEEP:-}" ] || rm -rf "$tmp"' EXIT
export HOME="$tmp/home" TERM=dumb
mkdir -p "$HOME"

pass() { passed=$((passed + 1)); }
fail() { echo "FAIL $*"; failed=$((failed + 1)); }
finish() { echo "$passed passed, $failed failed"; [ "$failed" = 0 ]; exit $?; }
show_tail() { tr -d '\r' <"$1" | tail -n 8 | sed 's/^/    /'; }

drive=$tmp/ptydrive
if ! cc -std=c99 -Wall -o "$drive" "$top/tests/shell/ptydrive.c" 2>"$tmp/cc.err"; then
    fail "tty: cannot build tests/shell/ptydrive.c"
    sed 's/^/    /' "$tmp/cc.err" | head -n 5
    finish
fi
[ -x "$vroc" ] || { fail "tty: no vroc in $build"; finish; }

# session SCRIPT-FILE TRANSCRIPT ARG...: runs vroc in $tmp, returns its status
session() {
    script=$1 tr=$2
    shift 2
    (cd "$tmp" && timeout 90 "$drive" "$tr" "$vroc" "$@" <"$script" 2>"$tr.drive")
}

# frames=N values of the stats lines in a transcript, in order
frames_of() { tr -d '\r' <"$1" | sed -n 's/^frames=\([0-9]*\) .*/\1/p'; }

# ---- session 1: prompt, completion, errors, real time, history ------------------------
cat >"$tmp/rt.cmd" <<'EOF'
time_step = 0.05
sphere fromread
  translate = (0, 10, 0)
  linear_vel = (0, 1, 0)
start
EOF
# a stats line while the session runs: its frames= is read back below
probe() { printf '%s\n' 'send stats\n' 'expect frames=' 'expect vroc> '; }
{
    cat <<'EOF'
expect type help
expect vroc> 
send sphere ball\n
expect vroc> 
send radi\t= 2\n
expect vroc> 
send sho\tbal\t\n
expect radius = 2
expect vroc> 
send help gravi\t\n
expect the same as force
expect vroc> 
send bogus\n
expect unknown command 'bogus'
expect vroc> 
send sphere junk\x03
send dump\n
expect ball,0,
expect vroc> 
send time_step = 0.05\n
send linear_vel = (1, 0, 0)\n
send start\n
expect vroc> 
sleep 0.8
EOF
    probe; echo 'sleep 0.5'; probe                          # running: frames grow
    printf '%s\n' 'send stop\n' 'expect vroc> '
    probe; echo 'sleep 0.5'; probe                          # stopped: they do not
    cat <<'EOF'
send read rt.cmd\n
expect vroc> 
sleep 0.6
send stop\n
expect vroc> 
send show fromread\n
expect name = fromread
expect vroc> 
EOF
    probe                                                   # after the read file's start
    cat <<'EOF'
send step 1000000000\n
sleep 0.5
send \x03
expect interrupted after
expect vroc> 
send quit\n
EOF
} >"$tmp/s1"
session "$tmp/s1" "$tmp/t1"
st=$?
if [ $st = 124 ] || [ $st = 125 ]; then
    fail "tty: session 1 timed out or could not start: $(cat "$tmp/t1.drive")"
    show_tail "$tmp/t1"
    finish
fi
pass   # every expect above was met: prompt, banner, completion, help, errors keep the session
[ $st = 1 ] && pass || fail "tty: exit status $st after a session with errors, expected 1"
grep -q 'VROC 0.1.0' "$tmp/t1" && pass || fail "tty: the banner does not name the version"
if grep -q 'junk' "$tmp/t1" && tr -d '\r' <"$tmp/t1" | grep -q '^junk,'; then
    fail "tty: Ctrl-C did not drop the line being typed"
else pass; fi

set -- $(frames_of "$tmp/t1")
if [ $# -ge 5 ]; then
    running1=$1 running2=$2 stopped1=$3 stopped2=$4 afterread=$5
    [ "$running1" -gt 0 ] && pass || fail "tty: start ran no frame in 0.8 s of real time (frames=$running1)"
    [ "$running2" -gt "$running1" ] && pass ||
        fail "tty: frames did not grow while the prompt answered ($running1 then $running2)"
    # 0.05 s frames: 0.8 s gives about 16; allow a slow machine, refuse a burst
    [ "$running1" -le 40 ] && pass || fail "tty: $running1 frames in 0.8 s at time_step 0.05: not real time"
    [ "$stopped1" = "$stopped2" ] && pass || fail "tty: frames went on after stop ($stopped1 then $stopped2)"
    [ "$afterread" -gt "$stopped2" ] && pass ||
        fail "tty: a read file's start did not run frames at the prompt ($stopped2 then $afterread)"
else
    fail "tty: expected 5 stats lines in the transcript, found $#"
    show_tail "$tmp/t1"
fi

hist=$HOME/.vroc_history
if [ -f "$hist" ] && grep -qx 'sphere ball' "$hist" && grep -qx 'show ball' "$hist" && grep -qx 'quit' "$hist"; then
    pass
else
    fail "tty: ~/.vroc_history does not hold the session's lines (with completions filled in)"
fi

# ---- session 2: the history is read back; Ctrl-D leaves with status 0 -------------
cat >"$tmp/s2" <<'EOF'
expect vroc> 
send \x10\x10\x10
sleep 0.2
send \x01\x0b
send sphere again\n
send dump\n
expect again,0,
expect vroc> 
send \x04
EOF
session "$tmp/s2" "$tmp/t2"
st=$?
[ $st = 0 ] && pass || { fail "tty: Ctrl-D after a clean session gave status $st, expected 0"; show_tail "$tmp/t2"; }
grep -q 'step 1000000000' "$tmp/t2" && pass || fail "tty: up-arrow (Ctrl-P) did not recall the previous session's history"

# Ctrl-D shows no second prompt: after the dump's line, one prompt (the one
# Ctrl-D answered), then the end
n=$(tr -d '\r' <"$tmp/t2" | awk '/^again,0,/ { f = 1; next } f' | grep -o 'vroc> ' | wc -l)
[ "$n" = 1 ] && pass || { fail "tty: after Ctrl-D the prompt came $n times, expected once"; show_tail "$tmp/t2"; }

# ---- session 5: Ctrl-C stops a running start; exit leaves ----------------------------
{
    cat <<'EOF2'
expect vroc> 
send time_step = 0.05\n
send sphere s\n
send linear_vel = (1, 0, 0)\n
send start\n
expect vroc> 
sleep 0.5
send \x03
expect start stopped by Ctrl-C
expect vroc> 
EOF2
    probe; echo 'sleep 0.5'; probe                          # stopped: the frames do not grow
    printf '%s\n' 'send exit\n'
} >"$tmp/s5"
session "$tmp/s5" "$tmp/t5"
st=$?
[ $st = 0 ] && pass || { fail "tty: Ctrl-C on a running start, then exit: status $st, expected 0"; show_tail "$tmp/t5"; }
set -- $(frames_of "$tmp/t5")
if [ $# = 2 ] && [ "$1" -gt 0 ] && [ "$1" = "$2" ]; then pass
else fail "tty: frames after Ctrl-C on start: '$*' (expected two equal counts > 0)"; show_tail "$tmp/t5"; fi

# ---- session 3: -i reads the files, then the prompt ------------------------------------
printf 'sphere fromfile\n  radius = 0.5\n' >"$tmp/first.cmd"
cat >"$tmp/s3" <<'EOF'
expect vroc> 
send dump\n
expect fromfile,0,
expect vroc> 
send quit\n
EOF
session "$tmp/s3" "$tmp/t3" -i first.cmd
st=$?
[ $st = 0 ] && pass || { fail "tty: vroc -i FILE at a terminal: status $st"; show_tail "$tmp/t3"; }

# ---- a file without -i at a terminal: batch, no prompt ----------------------------------
cat >"$tmp/s4" <<'EOF'
sleep 0.3
EOF
session "$tmp/s4" "$tmp/t4" first.cmd
st=$?
if [ $st = 0 ] && ! grep -q 'vroc> ' "$tmp/t4" && ! grep -q 'VROC' "$tmp/t4"; then pass
else fail "tty: vroc FILE at a terminal should run the file and exit, silently (status $st)"; fi

finish
