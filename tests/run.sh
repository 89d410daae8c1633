#!/bin/sh
# Runs the test runner BUILD/tests/vroc-tests (every tests/test_*.c) and
# every shell transcript test, prints each failure, and ends with one line
# `N passed, M failed`.
# Usage: tests/run.sh BUILD_DIR   (BUILD_DIR holds vroc, vroc-gp, tests/vroc-tests)
set -u
build=${1:?usage: tests/run.sh BUILD_DIR}
top=$(cd "$(dirname "$0")/.." && pwd)
passed=0 failed=0
# OSMesa and LLVM keep a little memory they never free (DEPENDENCIES.md)
export LSAN_OPTIONS="suppressions=$top/tests/lsan.supp:print_suppressions=0"
log=$(mktemp)
trap 'rm -f "$log"' EXIT

add_counts() { # add_counts NAME LOGFILE STATUS: take the suite's summary line
    line=$(tail -n 1 "$2")
    case "$line" in
    *" passed, "*" failed")
        p=${line%% passed*}; f=${line#*passed, }; f=${f%% failed*}
        passed=$((passed + p)); failed=$((failed + f))
        if [ "$3" != 0 ] && [ "$f" = 0 ]; then
            echo "FAIL $1: exit status $3 after its tests passed"; failed=$((failed + 1))
        fi ;;
    *)  echo "FAIL $1: no summary line (exit status $3; crashed?)"; failed=$((failed + 1)) ;;
    esac
    grep -E '^(FAIL|    )' "$2" | sed "s|^|[$1] |"
}

(cd "$top" && VROC_BUILD="$build" "$build/tests/vroc-tests") >"$log" 2>&1
add_counts vroc-tests "$log" $?
for s in "$top"/tests/*.sh; do
    case "$(basename "$s")" in run.sh) continue ;; esac
    name=$(basename "$s" .sh)
    (cd "$top" && VROC_BUILD="$build" sh "$s") >"$log" 2>&1
    add_counts "$name" "$log" $?
done
echo "$passed passed, $failed failed"
[ "$failed" = 0 ]
