#!/bin/sh
# The thesis scenes give the same dump after 200 frames serially and with
# 1, 2, 3 and 8 workers, both distributions, in process (memq://), and with
# 2 and 3 forked worker processes over UDP multicast (SPEC 5: trajectories
# equal the serial run's, bit for bit); and a scene of scaled OFF hulls
# and speed clamps, dump and stats.  Runs itself in a private network
# namespace; fails (never skips) when it cannot make one.
# Run by tests/run.sh from the repo root with VROC_BUILD set.
set -u
if [ -z "${VROC_NETNS:-}" ]; then
    exec unshare -n sh -c 'ip link set lo up && ip link set lo multicast on &&
        ip route add 224.0.0.0/4 dev lo && VROC_NETNS=1 exec sh "$0"' "$0" ||
        { echo "FAIL cannot make a private network namespace (unshare -n needs root)"; echo "0 passed, 1 failed"; exit 1; }
fi
vroc=${VROC_BUILD:-build/rel}/vroc
frames=200
passed=0 failed=0
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# agrees WHAT SERIAL PAR ERR: the run PAR printed SERIAL's text, and
# nothing on its standard error ERR
agrees() {
    if [ -s "$2" ] && cmp -s "$2" "$3" && [ ! -s "$4" ]; then
        passed=$((passed + 1))
    else
        echo "FAIL $1 differ from the serial run"
        diff "$2" "$3" | head -5; head -3 "$4"
        failed=$((failed + 1))
    fi
}

# the scene without its `start`, then a fixed number of frames and a dump
run() { # run SCENE GPS DISTRIBUTION OUT [URL]
    { printf 'gps = %s\ndistribution = %s\n' "$2" "$3"
      [ -z "${5:-}" ] || printf 'lcm_url = %s\n' "$5"
      sed '/^[[:space:]]*start[[:space:]]*\(#.*\)\{0,1\}$/d' "scenes/$1.cmd"
      printf 'step %s\ndump\n' "$frames"; } | "$vroc" -q >"$4" 2>"$4.err"
}

for scene in simple desks basketball office bounce; do
    if [ ! -f "scenes/$scene.cmd" ]; then
        echo "FAIL scenes/$scene.cmd is missing"; failed=$((failed + 1)); continue
    fi
    run "$scene" 0 round_robin "$tmp/serial"
    for cfg in "1 round_robin memq://" "2 round_robin memq://" "3 round_robin memq://" "8 round_robin memq://" \
        "1 improved memq://" "2 improved memq://" "3 improved memq://" "8 improved memq://" \
        "2 round_robin" "3 improved"; do
        set -- $cfg
        run "$scene" "$1" "$2" "$tmp/par" "${3:-}"
        agrees "$scene: $1 workers ($2${3:+, $3})" "$tmp/serial" "$tmp/par" "$tmp/par.err"
    done
done
# Issue 29: scaled OFF hulls (the workers get the scaled vertices as text)
# and speed clamps (the responder's spin clamp travels with the state) give
# the same dump and the same stats clamps= with workers as serially
clamp_scene() { # clamp_scene GPS [URL]
    printf 'gps = %s\n' "$1"
    [ -z "${2:-}" ] || printf 'lcm_url = %s\n' "$2"
    cat <<EOF2
gravity
cube floor
  size = (10, 10, 0.5)
  translate = (0, 0, -0.5)
  mass = -1
polyhedron mushroom
  file = $PWD/tests/shell/shapes/mushroom.off
  scale = (1, 2, 1.5)
  translate = (-4, 0, 2)
  angular_vel = (3, 0, 1)
polyhedron tall
  file = $PWD/tests/shell/shapes/tetra.coff
  scale = 2
  translate = (4, 0, 1)
cube a
  translate = (0, -3, 1.5)
  linear_vel = (0, 8, 0)
cube b
  translate = (0.8, 0, 1.5)
step 40
dump
stats
EOF2
}
clamp_scene 0 | "$vroc" -q 2>"$tmp/c.err" | sed -E 's/ [a-z_]+_ms=[0-9.]+//g; s/ (gps|messages|copies|gp_[a-z]+|foreign|malformed|live_pairs)=[^ ]*//g; s/ (checks|heap_pops|klu_[a-z]+)=[0-9]+//g' >"$tmp/c.serial"
grep -q 'clamps=[1-9]' "$tmp/c.serial" && passed=$((passed + 1)) ||
    { echo "FAIL clamps: the scene cut no velocity (stats clamps=0): it proves nothing"; failed=$((failed + 1)); }
for cfg in "2 memq://" "2" "3"; do
    set -- $cfg
    clamp_scene "$1" "${2:-}" | "$vroc" -q 2>"$tmp/c.err" |
        sed -E 's/ [a-z_]+_ms=[0-9.]+//g; s/ (gps|messages|copies|gp_[a-z]+|foreign|malformed|live_pairs)=[^ ]*//g; s/ (checks|heap_pops|klu_[a-z]+)=[0-9]+//g' >"$tmp/c.par"
    agrees "scaled hulls and clamps: $1 workers${2:+ ($2)}" "$tmp/c.serial" "$tmp/c.par" "$tmp/c.err"
done
# kept looks (keep_looks): a worker's walk goes past the answer to its own
# first event, so its pairs hold kept looks at several grid points; the
# physics fuzzer's seed 318 parted with 2 workers when a pair was looked
# at again at an earlier point (tests/data/keep_workers_seed318.cmd)
keep_scene() { # keep_scene GPS OUT
    { printf 'lcm_url = memq://\ngps = %s\n' "$1"; cat tests/data/keep_workers_seed318.cmd
      printf 'step 200\ndump\n'; } | "$vroc" -q >"$2" 2>"$2.err"
}
keep_scene 0 "$tmp/k.serial"
for g in 2 3; do
    keep_scene "$g" "$tmp/k.par"
    agrees "kept looks (fuzzer seed 318): $g workers" "$tmp/k.serial" "$tmp/k.par" "$tmp/k.par.err"
done
# the heap and the workers switched mid-run: the edit fuzzer's switch mode
# parted from the serial run at seeds 5, 14 and 16 of 1..40 (a switch threw
# the island step's warm starts away, src/owners.c vrOwners_Renew)
for seed in 5 14 16; do
    "$vroc" -q "tests/data/switch_seed$seed.cmd" >"$tmp/w.switch" 2>"$tmp/w.err"
    grep -v -E '^(gps|heap|distribution|lcm_url) = ' "tests/data/switch_seed$seed.cmd" >"$tmp/w.cmd"
    "$vroc" -q "$tmp/w.cmd" >"$tmp/w.serial" 2>>"$tmp/w.err"
    agrees "switched heap and workers (edit fuzzer seed $seed)" "$tmp/w.serial" "$tmp/w.switch" "$tmp/w.err"
done
# a worker killed mid-frame (the edit fuzzer's kill mode, seed 482: worker
# 1 dies in frame 6's second round) redoes the frame from its start, and
# the island steps must start warm from there too: they started from the
# killed frame's own last step, and the redone frame parted from serial
VROC_FAULT_KILL=1:6:2 "$vroc" -q tests/data/kill_seed482.cmd >"$tmp/x.kill" 2>"$tmp/x.err"
grep -v -E '^gps = ' tests/data/kill_seed482.cmd >"$tmp/x.cmd"
"$vroc" -q "$tmp/x.cmd" >"$tmp/x.serial" 2>>"$tmp/x.err"
agrees "a worker killed mid-frame (edit fuzzer seed 482)" "$tmp/x.serial" "$tmp/x.kill" "$tmp/x.err"
# answers that creep a rounding of t at a time close everything to the
# next grid point (allow_instant -1 on the wire): the workers agree
"$vroc" -q tests/data/creep_seed531.cmd >"$tmp/y.serial" 2>"$tmp/y.err"
{ printf 'lcm_url = memq://\ngps = 2\n'; cat tests/data/creep_seed531.cmd; } | "$vroc" -q >"$tmp/y.par" 2>>"$tmp/y.err"
agrees "creeping answers (edit fuzzer seed 531): 2 workers" "$tmp/y.serial" "$tmp/y.par" "$tmp/y.err"
echo "$passed passed, $failed failed"
[ "$failed" = 0 ]
