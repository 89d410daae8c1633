#!/bin/sh
# tools/scene-dumps.sh VROC OUT_DIR — runs every scenes/*.cmd to its end
# (its own `start`) with VROC and writes the final `dump` of each into
# OUT_DIR/NAME.dump, so that a refactoring can be shown to keep the same
# bits: run it before and after, then `cmp` the folders' files.
# Run from the repository root.  Exit status 1 when a scene fails.
set -u
vroc=${1:?usage: tools/scene-dumps.sh VROC OUT_DIR}
out=${2:?usage: tools/scene-dumps.sh VROC OUT_DIR}
mkdir -p "$out"
status=0
for s in scenes/*.cmd; do
    name=$(basename "$s" .cmd)
    printf 'read %s\ndump\n' "$(pwd)/$s" >"$out/$name.cmd"
    if ! "$vroc" "$out/$name.cmd" >"$out/$name.dump" 2>"$out/$name.err"; then
        echo "FAIL $name: $(head -n 1 "$out/$name.err")"
        status=1
    fi
    rm -f "$out/$name.cmd"
done
exit $status
