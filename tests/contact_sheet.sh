#!/bin/sh
# tests/contact_sheet.sh — tools/contact-sheet on frames in a folder given
# by a relative path (it used to fail for -a): the grid, the anaglyph and
# the stereo pair are written, and the anaglyph's pixel takes its red from
# the left eye and its green and blue from the right.  Needs netpbm (make
# deps); without it every case fails.  Ends with `N passed, M failed`.
set -u
top=$(pwd)
sheet=$top/tools/contact-sheet
passed=0 failed=0
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
pass() { passed=$((passed + 1)); }
fail() { echo "FAIL $*"; failed=$((failed + 1)); }

# ppm FILE R G B: a 2 x 2 frame of one colour
ppm() { { printf 'P6\n2 2\n255\n'; for i in 1 2 3 4; do printf "\\$(printf %03o "$2")\\$(printf %03o "$3")\\$(printf %03o "$4")"; done; } >"$1"; }
mkdir -p "$tmp/run/fr"
for n in 1 2 3; do
    ppm "$tmp/run/fr/frame-00000$n-left.ppm" 200 10 20
    ppm "$tmp/run/fr/frame-00000$n-right.ppm" 30 40 50
done
cd "$tmp/run"
for mode in "" "-a 2" "-s last"; do
    rm -f out.png
    if sh "$sheet" $mode fr out.png 2>err && [ -s out.png ]; then pass
    else fail "contact-sheet ${mode:-(grid)} fr out.png: $(cat err)"; fi
done
sh "$sheet" -a 2 fr ana.png 2>/dev/null
px=$(pngtopnm ana.png 2>/dev/null | pnmnoraw 2>/dev/null | sed -n 4p | awk '{ print $1, $2, $3 }')
[ "$px" = "200 40 50" ] && pass || fail "contact-sheet -a: the first pixel is '$px', expected '200 40 50' (left red, right green and blue)"
sh "$sheet" -a 9 fr x.png 2>err; st=$?
[ $st = 1 ] && grep -q 'no fr/frame-000009-left.ppm' err && pass || fail "contact-sheet -a 9: status $st, '$(cat err)'"
echo "$passed passed, $failed failed"
[ "$failed" = 0 ]
