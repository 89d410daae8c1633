#!/bin/sh
# make bench: runs every benchmark binary of the release build in turn.
# Each prints its own table (and CSV lines starting with `csv,`).
set -u
build=${1:-build/rel}
top=$(cd "$(dirname "$0")/.." && pwd)
echo "# VROC benchmarks — $(date -u +%Y-%m-%dT%H:%MZ)"
echo "# machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ *//')"
status=0
for b in "$build"/tests/bench_*; do
    [ -x "$b" ] || continue
    echo
    echo "## $(basename "$b")"
    (cd "$top" && VROC_BUILD="$build" "$b") || status=1
done
exit $status
