#!/bin/sh
# tests/shell.sh — transcripts of the vroc shell.
#
# Each tests/shell/NAME.cmd runs through $VROC_BUILD/vroc; its stdout,
# stderr and exit status must equal NAME.out, NAME.err and NAME.status
# beside it (a missing golden means: empty, status 0).  A first line
# `# args: OPTIONS` gives the command line; an `@` in it stands for the
# script itself as a file argument (stdin is then empty), otherwise the
# script is the standard input.  Cases run in a scratch copy of
# tests/shell, so that messages show short paths and frames land there.
# Wall-time keys (*_ms) are dropped from stats lines before comparing.
#
# Inputs that cannot live in a text file (a 1 MB line, NUL bytes, CRLF)
# are made below, with goldens beside the others; so are the checks of
# files vroc writes (frames) and the cross-check of `dump` against the
# library called directly (tests/shell/libdump.c).
#
# Goldens are written by hand from the SPEC; VROC_GOLDEN_WRITE=1 writes the
# current outputs instead, for reviewing a change line by line with git diff.
# Run from the repository root; ends with `N passed, M failed`.
set -u
top=$(pwd)
case ${VROC_BUILD:?set VROC_BUILD to the build folder} in
/*) build=$VROC_BUILD ;;
*) build=$top/$VROC_BUILD ;;
esac
vroc=$build/vroc
gold=$top/tests/shell
passed=0 failed=0
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
work=$tmp/work
mkdir -p "$work"
cp -R "$gold"/. "$work"/
export HOME="$tmp/home"   # never touch the real history
# OSMesa's process-wide allocations are not ours (what tests/run.sh sets)
export LSAN_OPTIONS="${LSAN_OPTIONS:-suppressions=$top/tests/lsan.supp:print_suppressions=0}"
mkdir -p "$HOME"

pass() { passed=$((passed + 1)); }
fail() { echo "FAIL $*"; failed=$((failed + 1)); }

same() { # same NAME WHAT EXPECTED-FILE ACTUAL-FILE
    if [ "${VROC_GOLDEN_WRITE:-}" = 1 ]; then
        if [ -s "$4" ]; then cp "$4" "$3"; else rm -f "$3"; fi
        return 0
    fi
    exp=$3
    [ -f "$exp" ] || exp=/dev/null
    cmp -s "$exp" "$4" && return 0
    echo "FAIL $1: $2 differs from $(basename "$3") (- expected, + got)"
    diff "$exp" "$4" | head -n 20 | sed 's/^/    /'
    return 1
}

# run_case NAME STDIN ARG...: runs vroc in the scratch folder, compares
run_case() {
    name=$1 input=$2
    shift 2
    (cd "$work" && timeout 120 "$vroc" "$@" <"$input" >"$tmp/out.raw" 2>"$tmp/err")
    status=$?
    sed -E 's/ [a-z_]+_ms=[0-9.]+//g' "$tmp/out.raw" >"$tmp/out"
    echo "$status" >"$tmp/status"
    ok=1
    same "$name" stdout "$gold/$name.out" "$tmp/out" || ok=0
    same "$name" stderr "$gold/$name.err" "$tmp/err" || ok=0
    if [ "${VROC_GOLDEN_WRITE:-}" = 1 ]; then
        if [ "$status" != 0 ]; then echo "$status" >"$gold/$name.status"; else rm -f "$gold/$name.status"; fi
    else
        want=0
        [ -f "$gold/$name.status" ] && want=$(cat "$gold/$name.status")
        if [ "$status" != "$want" ]; then
            echo "FAIL $name: exit status $status, expected $want"
            ok=0
        fi
    fi
    if [ $ok = 1 ]; then pass; else failed=$((failed + 1)); fi
}

if [ ! -x "$vroc" ]; then
    fail "shell: no vroc in $build"
    echo "$passed passed, $failed failed"
    exit 1
fi

# ---- the transcripts -----------------------------------------------------------
for cmd in "$gold"/*.cmd; do
    name=$(basename "$cmd" .cmd)
    args=$(sed -n '1s/^# args: *//p' "$cmd")
    if echo " $args " | grep -q ' @ '; then
        # shellcheck disable=SC2086
        set -- $(echo "$args" | sed "s|@|$name.cmd|")
        run_case "$name" /dev/null "$@"
    else
        # shellcheck disable=SC2086
        run_case "$name" "$work/$name.cmd" $args
    fi
done

# ---- inputs made here ------------------------------------------------------------
many() { head -c "$2" /dev/zero | tr '\0' "$1"; }   # many CHAR COUNT

# a line is a line whatever its length: 1 MB comments, words, blanks, digits
{
    printf '# '; many y 1000000; printf '\n'
    printf 'stats '; many x 1000000; printf '\n'
    many ' ' 1000000; printf 'sphere '; many z 1000000; printf '\n'
    printf 'time_step = '; many 0 1000000; printf '1\n'
    printf 'collision_dist = 0.'; many 0 1000000; printf '1\n'
    printf 'stats\n'
} >"$work/gen_long_line.in"
run_case gen_long_line "$work/gen_long_line.in"

# NUL bytes, control characters and binary junk: an error for that line only
printf 'sphere a\000b\nstats\001\n\377\376 junk\n\033[1m\n# \001 in a comment is fine\nsphere ok\ndump\n' >"$work/gen_binary.in"
run_case gen_binary "$work/gen_binary.in"
# a binary file (vroc itself) as input and as a file argument: errors, no crash, no hang
for how in stdin argument; do
    if [ $how = stdin ]; then (cd "$work" && timeout 60 "$vroc" <"$vroc" >/dev/null 2>"$tmp/bin.err")
    else (cd "$work" && timeout 60 "$vroc" "$vroc" </dev/null >/dev/null 2>"$tmp/bin.err"); fi
    st=$?
    if [ $st = 1 ] && grep -q 'not a text line' "$tmp/bin.err"; then pass
    else fail "gen_binary_file: the vroc binary on $how gave exit status $st, expected 1 and line errors"; fi
done

# CRLF line ends
printf 'sphere a\r\nradius = 2\r\n\r\n# comment\r\nlinear_vel = (1, 0, 0)  \r\nshow a\r\ndump\r\n' >"$work/gen_crlf.in"
run_case gen_crlf "$work/gen_crlf.in"

# command line: files in order, missing file, a folder, options
printf 'sphere first\n' >"$work/gen_first.cmd"
printf 'sphere second\ndump\n' >"$work/gen_second.cmd"
run_case gen_files_in_order /dev/null gen_first.cmd gen_second.cmd
run_case gen_missing_file /dev/null no-such-file.cmd gen_second.cmd
run_case gen_directory /dev/null sub
run_case gen_version /dev/null --version
run_case gen_bad_option /dev/null -z
run_case gen_bail_files /dev/null -b no-such-file.cmd gen_second.cmd
(cd "$work" && "$vroc" -h >"$tmp/h.out" 2>&1) && grep -q '^usage: vroc' "$tmp/h.out" && pass ||
    fail "gen_help_option: vroc -h does not print the usage with status 0"

# ---- frames: display, step, refresh, frames =, restart ---------------------------------
ppm_ok() { # ppm_ok FILE W H: header exactly P6\nW H\n255\n and W*H*3 bytes after it
    hdr="P6
$2 $3
255"
    [ -f "$1" ] && [ "$(head -n 3 "$1")" = "$hdr" ] &&
        [ "$(wc -c <"$1")" -eq $((${#hdr} + 1 + $2 * $3 * 3)) ]
}
rm -rf "$work/frames" "$work/out"
run_case gen_frames "$gold/frames.in"
missing=""
for f in 000000 000001 000002 000003; do
    for eye in left right; do
        ppm_ok "$work/out/frame-$f-$eye.ppm" 32 16 || missing="$missing $f-$eye"
    done
done
[ -z "$missing" ] && pass || fail "gen_frames: frames missing or malformed in out/:$missing"
[ ! -e "$work/out/frame-000004-left.ppm" ] && pass ||
    fail "gen_frames: 'frames =' (empty) did not stop writing (frame-000004 exists)"
[ ! -e "$work/frames" ] && pass || fail "gen_frames: the default folder ./frames was written although frames = out"
ppm_ok "$work/out2/frame-000001-right.ppm" 32 16 && [ ! -e "$work/out2/frame-000000-left.ppm" ] && pass ||
    fail "gen_frames: after restart, frames = out2 and step should write out2/frame-000001 only"

# the view reaches the renderer: reset restores the pose, see_through = 2
# hides real objects (tests/shell/views.in)
run_case gen_views "$gold/views.in"
f=frame-000000-left.ppm
if cmp -s "$work/v1/$f" "$work/v3/$f" && ! cmp -s "$work/v1/$f" "$work/v2/$f"; then pass
else fail "gen_views: eye/look/up did not change the frame, or reset did not restore it (v1, v2, v3)"; fi
if cmp -s "$work/e1/$f" "$work/e2/$f" && ! cmp -s "$work/e1/$f" "$work/e3/$f"; then pass
else fail "gen_views: see_through = 2 did not hide the real = 1 object, or = 0 did not show it (e1, e2, e3)"; fi

# a tracked head drives the view; reset gives it back (tests/shell/head_track.in)
run_case gen_head_track "$gold/head_track.in"
f0=frame-000000-left.ppm f1=frame-000001-left.ppm
black() { [ "$(tail -c +14 "$1" | tr -d '\000' | wc -c)" = 0 ]; }
if cmp -s "$work/h1/$f0" "$work/h2/$f0" && ! cmp -s "$work/d0/$f0" "$work/h1/$f0" && black "$work/h2/$f1" &&
    ! black "$work/h1/$f0" && cmp -s "$work/d0/$f0" "$work/h3/$f1"; then pass
else fail "gen_head_track: the head's pose did not drive the view (h1 = h2, h2/1 black), or reset did not restore it (h3 = d0)"; fi

# sound_log: a header and one line t,sound,volume,x,y,z,speed per impact
# faster than sound_min_speed (the physics is tests/test_sound.c's), the
# sound named by collision_sound; tools/vroc-sound renders it
run_case gen_sound_log "$gold/sound_log.in"
lines=$(grep -vc '^#' "$work/sound.log" 2>/dev/null)
if [ "$(head -n 1 "$work/sound.log" 2>/dev/null)" = "# t,sound,volume,x,y,z,speed" ] && [ "$lines" -ge 3 ] &&
    ! grep -v '^#' "$work/sound.log" | grep -qv '^[0-9.e-]*,bounce,[0-9.e-]*,[0-9.e-]*,[0-9.e-]*,[0-9.e-]*,[0-9.e-]*$' &&
    [ "$(grep -vc '^#' "$work/quiet.log")" = 0 ] && "$build/vroc-sound" "$work/sound.log" "$work/sound.wav" &&
    [ "$(head -c 4 "$work/sound.wav")" = RIFF ]; then pass
else fail "gen_sound_log: sound.log ($lines events) or quiet.log (sound_min_speed = 100: none) or vroc-sound's WAV is wrong"; fi

# a display that cannot open is an error of that line, and the shell goes on
printf 'display\nsphere a\ndump\n' | (cd "$work" && VROC_RENDER_MODULE=/nonexistent/vroc-render.so timeout 60 "$vroc" \
    >"$tmp/out" 2>"$tmp/err")
st=$?
if [ $st = 1 ] && grep -q '^vroc: <stdin>:1: ' "$tmp/err" && [ "$(wc -l <"$tmp/err")" = 1 ] && grep -q '^a,0,' "$tmp/out"; then pass
else fail "gen_no_render_module: display without a render module: status $st, expected 1 and one error for line 1"; fi

# seed reaches the random stream: the same seed draws the same scene after
# restart, another seed another one
printf 'seed = 7\nrandom 2\ndump\nrestart\nrandom 2\ndump\nseed = 8\nrestart\nrandom 2\ndump\n' |
    (cd "$work" && timeout 60 "$vroc" >"$tmp/seed.out" 2>&1)
sed -n '1,3p' "$tmp/seed.out" >"$tmp/seed.a"
sed -n '4,6p' "$tmp/seed.out" >"$tmp/seed.b"
sed -n '7,9p' "$tmp/seed.out" >"$tmp/seed.c"
if [ "$(wc -l <"$tmp/seed.out")" = 9 ] && cmp -s "$tmp/seed.a" "$tmp/seed.b" && ! cmp -s "$tmp/seed.a" "$tmp/seed.c"; then pass
else fail "gen_seed: seed = 7 twice should draw the same random scene, seed = 8 another"; fi

# ---- dump after a scripted run = the library called directly -------------------------
ldflags="-lccd -lklu -llcm -ldl -lm"
libdump=$tmp/libdump
cc -std=c99 -D_POSIX_C_SOURCE=200809L -I"$top/include" -o "$libdump" "$gold/libdump.c" "$build/libvroc.a" $ldflags \
    >/dev/null 2>&1 ||
    cc -std=c99 -D_POSIX_C_SOURCE=200809L -fsanitize=address,undefined -I"$top/include" -o "$libdump" \
        "$gold/libdump.c" "$build/libvroc.a" $ldflags >"$tmp/cc.err" 2>&1
if [ ! -x "$libdump" ]; then
    fail "libdump: cannot build tests/shell/libdump.c against $build/libvroc.a"
    sed 's/^/    /' "$tmp/cc.err" | head -n 10
else
    (cd "$work" && timeout 120 "$vroc" -q <"$gold/libdump.in" >"$tmp/shell.dump" 2>"$tmp/shell.err")
    st=$?
    timeout 120 "$libdump" >"$tmp/lib.dump" 2>"$tmp/lib.err"
    if [ $st != 0 ] || [ -s "$tmp/shell.err" ]; then
        fail "libdump: vroc failed on libdump.in (status $st)"
        sed 's/^/    /' "$tmp/shell.err" | head -n 5
    elif ! cmp -s "$tmp/lib.dump" "$tmp/shell.dump"; then
        fail "libdump: vroc's dump differs from the library's"
        diff "$tmp/lib.dump" "$tmp/shell.dump" | head -n 10 | sed 's/^/    /'
    elif [ "$(grep -c . "$tmp/shell.dump")" -lt 6 ]; then
        fail "libdump: the dumps are too short"
    else
        pass
    fi
fi

echo "$passed passed, $failed failed"
[ "$failed" = 0 ]
