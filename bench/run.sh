#!/bin/sh
# make bench: runs every benchmark of the release build in turn
# (BUILD/bench/bench_*, built from bench/bench_*.c), from the repo root.
# Each prints its own table (and CSV lines starting with `csv,`); bench_ode
# runs the peers' rooms in ODE (libode-dev, installed by make bench) and in
# vroc, interleaved, and prints the ratio of the same minutes (issue 26).
# Usage: bench/run.sh [BUILD_DIR]   (build/rel when not given)
set -u
build=${1:-build/rel}
top=$(cd "$(dirname "$0")/.." && pwd)
echo "# VROC benchmarks — $(date -u +%Y-%m-%dT%H:%MZ)"
echo "# machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ *//')"
status=0
for b in "$build"/bench/bench_*; do
    [ -x "$b" ] || continue
    echo
    echo "## $(basename "$b")"
    (cd "$top" && VROC_BUILD="$build" "$b") || status=1
done
exit $status
