#!/bin/sh
# tools/fuzz/afl.sh SECONDS TARGET... — make fuzz's runner (SPEC 11).
# Runs afl-fuzz on each target's harness (build/fuzz/fuzz-TARGET) for its
# share of SECONDS, from a corpus seeded from scenes/ and tests/shell
# (shell), the OFF files of tests/ (off), or lcm-seeds (lcm), and ends
# with `fuzz: N execs, M crashes, K hangs`.  Everything goes under
# build/fuzz/TARGET/: in/ (seeds), out/ (AFL++'s queue, crashes, hangs),
# work/ (the harness's current folder).  A target's earlier out/ is
# resumed, so that a long run can be made of short ones.  The run is made
# in a private network namespace when unshare -n is allowed: a harness
# never sends, but nothing fuzzed may reach a real network.
set -eu
secs=${1:?usage: afl.sh SECONDS TARGET...}; shift
top=$(cd "$(dirname "$0")/../.." && pwd)
cd "$top"
if [ -z "${VROC_NETNS:-}" ] && unshare -n true 2>/dev/null; then
    exec unshare -n sh -c 'ip link set lo up && VROC_NETNS=1 exec sh "$0" "$@"' "$0" "$secs" "$@"
fi
each=$((secs / $#)); [ "$each" -ge 1 ] || each=1
# a shared machine: no core binding, no CPU-governor check, no core_pattern demand
export AFL_NO_AFFINITY=1 AFL_SKIP_CPUFREQ=1 AFL_I_DONT_CARE_ABOUT_MISSING_CRASHES=1
export AFL_NO_UI=1 AFL_QUIET=1 AFL_SKIP_BIN_CHECK=1
# an earlier out/ is resumed (AFL++'s -i -), a missing one started from in/
export AFL_AUTORESUME=1

seed() { # seed TARGET DIR: the first corpus
    case $1 in
    shell) for f in scenes/*.cmd tests/shell/*.cmd; do cp "$f" "$2/$(echo "$f" | tr / _)"; done ;;
    off)   for f in $(find tests scenes -name '*.off'); do cp "$f" "$2/$(echo "$f" | tr / _)"; done ;;
    lcm)   build/fuzz/lcm-seeds "$2" ;;
    *)     echo "afl.sh: unknown target '$1' (shell, off, lcm)" >&2; exit 2 ;;
    esac
}

stat() { # stat FILE KEY: a fuzzer_stats value (0 when absent)
    v=$(sed -n "s/^$2 *: *//p" "$1" 2>/dev/null | head -n 1)
    echo "${v:-0}"
}

execs=0 crashes=0 hangs=0
for t in "$@"; do
    d=build/fuzz/$t
    mkdir -p "$d/in" "$d/out" "$d/work"
    [ -n "$(ls "$d/in")" ] || seed "$t" "$d/in"
    # -t: a hang is an input still running after 5 s (the shell's harness
    # interrupts a long run after 25 ms of CPU: only a stuck frame gets there)
    (cd "$d/work" && afl-fuzz -V "$each" -t 5000 -m none -i "$top/$d/in" \
        -o "$top/$d/out" -- "$top/build/fuzz/fuzz-$t") >"$d/afl.log" 2>&1 ||
        { echo "afl.sh: afl-fuzz failed on $t, see $d/afl.log:" >&2; tail -n 5 "$d/afl.log" >&2; exit 1; }
    s=$d/out/default/fuzzer_stats
    n=$(stat "$s" execs_done) c=$(stat "$s" saved_crashes) h=$(stat "$s" saved_hangs)
    echo "fuzz $t: $n execs, $c crashes, $h hangs ($d/out/default/crashes, hangs)"
    execs=$((execs + n)) crashes=$((crashes + c)) hangs=$((hangs + h))
done
echo "fuzz: $execs execs, $crashes crashes, $hangs hangs"
