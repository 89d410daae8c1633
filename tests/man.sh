#!/bin/sh
# tests/man.sh — the manual and the parser agree: every command and
# attribute that `help` lists (the parser's own table) has a tagged
# paragraph in man/vroc.1 with the same syntax, and `help NAME` describes
# it; every command the manual tags is one vroc knows; groff renders the
# page without warnings; help fits 80 columns; vroc-gp.1 is there.
# Ends with `N passed, M failed`.
set -u
top=$(pwd)
case ${VROC_BUILD:?set VROC_BUILD to the build folder} in
/*) build=$VROC_BUILD ;;
*) build=$top/$VROC_BUILD ;;
esac
vroc=$build/vroc
page=$top/man/vroc.1
passed=0 failed=0
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

pass() { passed=$((passed + 1)); }
fail() { echo "FAIL $*"; failed=$((failed + 1)); }
finish() { echo "$passed passed, $failed failed"; [ "$failed" = 0 ]; exit $?; }

[ -f "$page" ] || { fail "man: no man/vroc.1"; finish; }
[ -x "$vroc" ] || { fail "man: no vroc in $build"; finish; }

# groff: no warnings at all (-ww), and it renders
if groff -man -Tutf8 -ww -P-cbu "$page" >"$tmp/raw" 2>"$tmp/warn" && [ ! -s "$tmp/warn" ]; then pass
else
    fail "man: groff -man -ww warns about man/vroc.1"
    head -n 5 "$tmp/warn" | sed 's/^/    /'
fi
for s in NAME SYNOPSIS DESCRIPTION OPTIONS COMMANDS "SCENE FILES" "OUTPUT FORMATS" PHYSICS "EXIT STATUS" FILES \
    ENVIRONMENT EXAMPLES "SEE ALSO"; do
    grep -q "^\.SH \"*$s\"*\$" "$page" || fail "man: no section $s"
done
pass

# the rendered text, one line each, blanks trimmed, typographic dashes plain
LC_ALL=C sed 's/\xe2\x80\x90/-/g; s/\xe2\x88\x92/-/g; s/^ *//; s/ *$//' "$tmp/raw" >"$tmp/man.txt"

# the parser's table, as help prints it: "  SYNTAX   description"
echo help | "$vroc" >"$tmp/help" 2>"$tmp/help.err"
grep '^  [a-z]' "$tmp/help" | sed 's/^  //; s/  .*//' >"$tmp/syntax"
n=$(wc -l <"$tmp/syntax")
if [ "$n" -ge 60 ] && [ ! -s "$tmp/help.err" ]; then pass
else fail "man: help lists $n commands (expected every command and attribute, 60 or more)"; fi

while IFS= read -r syn; do
    name=${syn%% *}
    # a short tag shares its line with the paragraph: "stop   Stop time."
    if awk -v s="$syn" 'index($0, s) == 1 && (length($0) == length(s) || substr($0, length(s) + 1, 1) == " ") { f = 1 }
                        END { exit !f }' "$tmp/man.txt"; then pass
    else fail "man: '$syn' (from help) has no tagged paragraph in man/vroc.1"; fi
    first=$(echo "help $name" | "$vroc" 2>/dev/null | head -n 1)
    if [ "$first" = "$syn" ]; then pass
    else fail "man: 'help $name' does not describe '$syn' (got '$first')"; fi
done <"$tmp/syntax"

# help fits a terminal of 80 columns, the listing and each `help NAME`
wide=$(awk 'length > 80' "$tmp/help" | head -n 3)
[ -z "$wide" ] && pass || fail "man: help has lines wider than 80 columns: $wide"
while IFS= read -r syn; do echo "help ${syn%% *}"; done <"$tmp/syntax" | "$vroc" >"$tmp/helps" 2>&1
wide=$(awk 'length > 80' "$tmp/helps" | head -n 3)
[ -z "$wide" ] && pass || fail "man: help NAME has lines wider than 80 columns: $wide"

# SEE ALSO names vroc-gp(1): its page is here, renders without warnings,
# and make install installs it
gp=$top/man/vroc-gp.1
if [ -f "$gp" ] && groff -man -Tutf8 -ww "$gp" >/dev/null 2>"$tmp/gpwarn" && [ ! -s "$tmp/gpwarn" ]; then pass
else fail "man: man/vroc-gp.1, named in SEE ALSO, is missing or groff warns about it"; fi
grep -q 'man/vroc-gp\.1' "$top/Makefile" && pass || fail "man: make install does not install man/vroc-gp.1"

# the other way: every command the manual tags (a bold word at the start of
# a .TP/.TQ tag in COMMANDS) is one the parser knows
sed -n '/^\.SH COMMANDS/,/^\.SH SCENE/p' "$page" |
    awk '/^\.(TP|TQ)$/ { getline; if ($1 ~ /^\.B/) { w = $2; gsub(/"/, "", w); print w } }' |
    sed 's/\\f[BIRP]//g' | sort -u >"$tmp/tagged"
[ -s "$tmp/tagged" ] || fail "man: found no tagged commands in COMMANDS"
while IFS= read -r w; do
    if echo "help $w" | "$vroc" >/dev/null 2>&1; then pass
    else fail "man: man/vroc.1 documents '$w', which vroc does not know"; fi
done <"$tmp/tagged"

finish
