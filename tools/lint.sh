#!/bin/sh
# tools/lint.sh — make lint: cppcheck, clang-tidy (the checks of .clang-tidy,
# listed there with the reasons) and gcc -fanalyzer on every C file of the
# library, the shell and the fuzz harnesses.  Prints each finding and ends
# with `lint: N findings (cppcheck C, clang-tidy T, gcc -fanalyzer A)`;
# exits 1 when N > 0.  A false positive is silenced where it is, with a
# comment that says why (NOLINT(check) for clang-tidy, cppcheck-suppress
# ID for cppcheck, a #pragma for gcc), never by turning a check off here.
# Run from the repository root, after the LCM types are generated (make
# does that): the parallel code includes build/gen's headers.
set -u
jobs=${LINT_JOBS:-2}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
lib_inc="-Iinclude -Isrc -Isrc/parallel -Ibuild/gen -isystem /usr/include/suitesparse"
defs="-std=c99 -D_POSIX_C_SOURCE=200809L"
files=$(ls src/*.c src/parallel/*.c shell/*.c tools/fuzz/*.c)

for tool in cppcheck clang-tidy gcc; do
    command -v $tool >/dev/null 2>&1 || { echo "lint: $tool is not installed (make deps: tools/install-deps.sh lint)"; exit 1; }
done


# cppcheck: the bug classes (warning), portability and performance; style is
# ours to choose.  quickhull.c's horizon walk keeps a pointer into its own
# stack array that cppcheck takes for a local object indexed past its end
# (objectIndex): one file's one pattern, so it is named here.
cppcheck -q -j "$jobs" --std=c99 --enable=warning,portability,performance --inline-suppr \
    --error-exitcode=0 -D_POSIX_C_SOURCE=200809L -Iinclude -Isrc -Isrc/parallel -Ibuild/gen -Ishell \
    --suppress=missingIncludeSystem --suppress=objectIndex:src/quickhull.c \
    --template='{file}:{line}: cppcheck {severity}: {message} [{id}]' $files 2>"$tmp/cppcheck"

# clang-tidy, one file at a time, $jobs at once
for f in $files; do echo "$f"; done | xargs -P "$jobs" -I{} sh -c '
    f={}; case $f in shell/*) inc="-Iinclude" ;; tools/fuzz/*) inc="$0 -Ishell" ;; *) inc="$0" ;; esac
    clang-tidy -quiet "$f" -- '"$defs"' $inc >"'"$tmp"'/tidy.$(echo "$f" | tr / _)" 2>/dev/null' "$lib_inc"
cat "$tmp"/tidy.* | grep -E '(warning|error):' | sed "s|^$(pwd)/||" | sort -u >"$tmp/tidy"

# gcc -fanalyzer at -O0, where it sees the code as written
for f in $files; do echo "$f"; done | xargs -P "$jobs" -I{} sh -c '
    f={}; case $f in shell/*) inc="-Iinclude" ;; tools/fuzz/*) inc="$0 -Ishell" ;; *) inc="$0" ;; esac
    gcc '"$defs"' $inc -fanalyzer -c "$f" -o /dev/null 2>&1 | grep -E "(warning|error):"' "$lib_inc" | sort -u >"$tmp/analyzer"

c=$(grep -c . "$tmp/cppcheck") t=$(grep -c . "$tmp/tidy") a=$(grep -c . "$tmp/analyzer")
cat "$tmp/cppcheck" "$tmp/tidy" "$tmp/analyzer"
echo "lint: $((c + t + a)) findings (cppcheck $c, clang-tidy $t, gcc -fanalyzer $a)"
[ $((c + t + a)) = 0 ]
