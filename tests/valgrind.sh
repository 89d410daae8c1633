#!/bin/sh
# tests/valgrind.sh — valgrind finds nothing (SPEC 11): memcheck runs vroc
# on tests/valgrind/features.cmd (objects of every kind, errors on purpose,
# time with the heap on and off, start, random scenes, workers in this
# process over memq://), on every shell transcript of tests/shell (the
# parser's errors, bail, read, quit ...), and on binary junk.  Everything
# but the drawing (OSMesa, the window): no script here draws.
#
# valgrind cannot run an ASan build, so this runs the release build,
# $VROC_VALGRIND_BUILD (default build/rel): make check builds it.  Any
# error, or a leak that is definite, indirect or possible, fails the case;
# tests/valgrind.supp holds what LCM's glib keeps, with the reason.  Without
# valgrind the suite fails (make deps installs it): it never skips.
# Run from the repository root; ends with `N passed, M failed`.
set -u
top=$(pwd)
build=${VROC_VALGRIND_BUILD:-build/rel}
case $build in /*) ;; *) build=$top/$build ;; esac
vroc=$build/vroc
passed=0 failed=0
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
work=$tmp/work
mkdir -p "$work/shell" "$work/valgrind" "$work/data" "$tmp/home"
cp -R "$top"/tests/shell/. "$work/shell"/
cp -R "$top"/tests/valgrind/. "$work/valgrind"/
cp -R "$top"/tests/data/. "$work/data"/
export HOME="$tmp/home"   # never touch the real history

summary() {
    echo "$passed passed, $failed failed"
    [ "$failed" = 0 ]
    exit
}
if ! command -v valgrind >/dev/null 2>&1; then
    echo "FAIL valgrind: valgrind is not installed (make deps installs it)"
    failed=1
    summary
fi
if [ ! -x "$vroc" ]; then
    echo "FAIL valgrind: no vroc in $build (make rel-all builds it)"
    failed=1
    summary
fi

# vg NAME DIR STDIN ARG...: vroc under memcheck in DIR; exit status 99 is valgrind's
vg() {
    name=$1 dir=$2 input=$3
    shift 3
    (cd "$dir" && timeout 600 valgrind -q --error-exitcode=99 --leak-check=full \
        --show-leak-kinds=definite,indirect,possible --errors-for-leak-kinds=definite,indirect,possible \
        --suppressions="$top/tests/valgrind.supp" --log-file="$tmp/vg.log" \
        "$vroc" "$@" <"$input" >/dev/null 2>"$tmp/err")
    status=$?
    if [ "$status" = 99 ] || [ "$status" -gt 2 ] || [ -s "$tmp/vg.log" ]; then
        echo "FAIL valgrind $name: exit status $status"
        sed 's/^/    /' "$tmp/vg.log" | head -n 40
        failed=$((failed + 1))
    else
        passed=$((passed + 1))
    fi
}

vg features "$work/valgrind" /dev/null -q features.cmd
for cmd in "$work"/shell/*.cmd; do
    name=$(basename "$cmd" .cmd)
    args=$(sed -n '1s/^# args: *//p' "$cmd")
    # shellcheck disable=SC2086
    if echo " $args " | grep -q ' @ '; then
        vg "shell/$name" "$work/shell" /dev/null $(echo "$args" | sed "s|@|$name.cmd|")
    else
        vg "shell/$name" "$work/shell" "$cmd" $args
    fi
done
printf 'sphere a\000b\nstats\001\n\377\376 junk\n\033[1m\nsphere ok\ndump\n' >"$work/junk.in"
vg junk "$work" "$work/junk.in"
vg binary "$work" "$vroc"
summary
