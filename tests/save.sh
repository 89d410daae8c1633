#!/bin/sh
# tests/save.sh — `save FILE` (SPEC 11): a run saved after k frames and
# continued m frames must give, bit for bit, the dump and stats (but the
# wall-time *_ms keys) that a fresh vroc gives reading the file and
# running the same m frames.  Each case is a scene S and what both runs
# do after the save (A: the saving run goes on; B: a fresh `vroc` reads
# the file and goes on).  The cases: an elastic room of random objects
# (the random stream, and `random` again after the save), a frictional
# pile partly at rest (islands, rest, warm starts: the file must hold
# them), the thesis's Office, polyhedra from OFF files, objects deleted
# and made mid-run (ids kept by `state gap`), the heap off, and a serial
# save continued with 2 workers (in process and forked over multicast in
# a private network namespace).  Then the text format is pinned by a
# golden (tests/shell/save_small.vroc) and a saved file re-saved by its
# reader must be the same file.  Fails, never skips.
# Run by tests/run.sh from the repo root with VROC_BUILD set.
set -u
if [ -z "${VROC_NETNS:-}" ]; then
    exec unshare -n sh -c 'ip link set lo up && ip link set lo multicast on &&
        ip route add 224.0.0.0/4 dev lo && VROC_NETNS=1 exec sh "$0"' "$0" ||
        { echo "FAIL cannot make a private network namespace (unshare -n needs root)"; echo "0 passed, 1 failed"; exit 1; }
fi
top=$(pwd)
vroc=$top/${VROC_BUILD:-build/rel}/vroc
case ${VROC_BUILD:-} in /*) vroc=$VROC_BUILD/vroc ;; esac
passed=0 failed=0
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cd "$tmp" || exit 1

pass() { passed=$((passed + 1)); }
fail() { echo "FAIL $*"; failed=$((failed + 1)); }

# the wall-time keys go; everything else must match
no_ms() { sed 's/ [a-z_]*_ms=[^ ]*//g' "$1"; }

# two_runs NAME K AFTER: scene $NAME.cmd, k frames, save; AFTER (a file of
# statements) run by A and by B; their outputs compared
two_runs() {
    { cat "$1.cmd"; echo "step $2"; echo "save $1.vroc"; cat "$3"; } | "$vroc" -q >"$1.a" 2>"$1.a.err"
    { cat "$1.vroc" "$3"; } | "$vroc" -q >"$1.b" 2>"$1.b.err"
    if [ ! -s "$1.vroc" ]; then fail "$1: no save file written"; cat "$1.a.err"; return; fi
    if [ -s "$1.a.err" ] || [ -s "$1.b.err" ]; then fail "$1: errors"; head -5 "$1.a.err" "$1.b.err"; return; fi
    if ! grep -q '^# name,' "$1.a"; then fail "$1: no dump"; return; fi
    no_ms "$1.a" >"$1.a.cmp"; no_ms "$1.b" >"$1.b.cmp"
    if cmp -s "$1.a.cmp" "$1.b.cmp"; then pass; else fail "$1: the saving run and the reader differ"; diff "$1.a.cmp" "$1.b.cmp" | head -6; fi
}

after() { printf '%s\n' "$@" >after.cmd; }

# ---- an elastic room of random objects -----------------------------------------
cat >room.cmd <<'S'
time_step = 0.05
collision_dist = 0.05
seed = 11
room = 2
max_linear = 4
random 7
S
after "step 30" "dump" "stats" "random 2" "step 20" "dump" "stats"
two_runs room 23 after.cmd
# the stream went on from where it was, not from the seed: the two new
# objects differ from the first two of the seed
if grep -q '^r7,' room.a && [ "$(grep '^r0,' room.vroc | head -1)" = "" ]; then pass
else fail "room: random objects after the save missing"; fi

# ---- a frictional pile, partly resting ------------------------------------------
cat >pile.cmd <<'S'
time_step = 0.02
collision_dist = 0.02
gravity
default_friction = 0.6
default_elasticity = 0.1
cube floor
  size = (3, 3, 0.1)
  mass = -1
cube b0
  size = (0.1, 0.1, 0.1)
  translate = (0, 0, 0.2)
cube b1
  size = (0.1, 0.1, 0.1)
  translate = (0.02, 0.01, 0.41)
cube b2
  size = (0.1, 0.1, 0.1)
  translate = (1, 0, 0.2)
sphere s0
  radius = 0.1
  translate = (-1, 0, 1.5)
  linear_vel = (0.5, 0, 0)
sphere s1
  radius = 0.08
  translate = (1.01, 0.02, 2)
S
after "step 40" "dump" "stats"
two_runs pile 40 after.cmd
# the case proves something only if the save holds rest and warm starts
if grep -q ' rest=1 ' pile.vroc && grep -q ' rest=0 .*contact=1\| rest=0 ' pile.vroc && grep -q '^state warm ' pile.vroc
then pass; else fail "pile: the save holds no resting body or no warm start"; fi
after "heap = 0" "step 40" "dump" "stats"
two_runs pile 40 after.cmd
sed 's/^gravity$/gravity\nheap = 0/' pile.cmd >pileoff.cmd
after "step 40" "dump" "stats"
two_runs pileoff 25 after.cmd

# ---- the thesis's Office ------------------------------------------------------
sed '/^[[:space:]]*start[[:space:]]*\(#.*\)\{0,1\}$/d' "$top/scenes/office.cmd" >office.cmd
after "step 60" "dump" "stats"
two_runs office 70 after.cmd

# ---- polyhedra from OFF files ------------------------------------------------
cat >octa.off <<'S'
OFF 6 8 12
# an octahedron about (10, -5, 7)
11 -5 7
9 -5 7
10 -4 7
10 -6 7
10 -5 8
10 -5 6
3 0 2 4
3 2 1 4
3 1 3 4
3 3 0 4
3 2 0 5
3 1 2 5
3 3 1 5
3 0 3 5
S
cat >poly.cmd <<S
time_step = 0.05
collision_dist = 0.05
gravity
cube floor
  size = (20, 20, 0.5)
  translate = (0, 0, -0.5)
  mass = -1
polyhedron box
  file = $top/tests/data/cube.off
  translate = (0, 0, 3.6)
  angular_vel = (0.3, 1, 0.2)
polyhedron dent
  file = octa.off
  translate = (0.3, 0.2, 8)
  angular_vel = (1, 0, 0.5)
  elasticity = 0.5
S
after "step 40" "dump" "stats"
two_runs poly 12 after.cmd

# ---- objects deleted and made mid-run ------------------------------------------
{ cat room.cmd; echo "step 10"; echo "delete r2"; echo "delete r6"
  echo "sphere late"; echo "  radius = 0.1"; echo "  translate = (0, 0, 0.3)"; echo "  linear_vel = (1, 0.5, 0)"; } >edits.cmd
after "step 10" "delete r4" "cube later" "  size = (0.1, 0.05, 0.1)" "  translate = (0.4, 0.4, 0.5)" "step 20" "dump" "stats"
two_runs edits 10 after.cmd
if [ "$(grep -c '^state gap$' edits.vroc)" = 2 ]; then pass; else fail "edits: two deleted ids should give two gaps"; fi

# a rough room: friction, a superquadric, a resting body deleted at once
# after the save (its island wakes in both runs: the reader's objects
# are live when the file ends, `state live`)
cat >rough.cmd <<'S'
time_step = 0.03
collision_dist = 0.03
gravity
default_friction = 0.4
default_elasticity = 0.3
seed = 5
room = 3
random 10
superquadric sq
  exp1 = 0.5
  exp2 = 1.5
  a1 = 0.1
  a2 = 0.15
  a3 = 0.1
  translate = (0.2, 0.3, 1.2)
  angular_vel = (1, 2, 0.5)
S
after "delete r3" "step 30" "sphere nw" "  radius = 0.05" "  translate = (0, 0, 1.3)" "step 30" "dump" "stats"
two_runs rough 45 after.cmd
if grep -q '^  state body.* rest=1 ' rough.vroc; then pass; else fail "rough: nothing rests at the save"; fi
after "start" "dump" "stats"
two_runs rough 90 after.cmd

# ---- a serial save continued with two workers ----------------------------------
after "gps = 2" "lcm_url = memq://" "step 40" "dump" "stats"
two_runs pile 30 after.cmd
cp pile.a pile.memq
after "gps = 2" "step 40" "dump" "stats"
two_runs pile 30 after.cmd
after "step 40" "dump" "stats"
two_runs pile 30 after.cmd
# workers or not, the same bodies
grep -v '^frames=' pile.a >p1; grep -v '^frames=' pile.memq >p2
if [ -s p1 ] && cmp -s p1 p2; then pass; else fail "pile: serial and 2 workers differ after the save"; fi

# saved from a run with workers, read with workers
sed 's/^gravity$/gravity\ngps = 2\nlcm_url = memq:\/\//' pile.cmd >pilegp.cmd
after "step 30" "dump" "stats"
two_runs pilegp 25 after.cmd
grep -v '^frames=' pilegp.a >p3
{ cat pile.cmd; echo "step 55"; echo "dump"; } | "$vroc" -q | grep -v '^frames=' >p4
if [ -s p3 ] && cmp -s p3 p4; then pass; else fail "pilegp: a save with workers moved the bodies off the serial run's"; fi

# ---- the text format -------------------------------------------------------------
cat >small.cmd <<'S'
time_step = 0.1
gravity
cube floor
  size = (1, 1, 0.1)
  mass = -1
sphere ball
  radius = 0.1
  translate = (0, 0, 0.5)
  elasticity = 0.5
S
{ cat small.cmd; echo "step 3"; echo "save small.vroc"; } | "$vroc" -q 2>small.err
if cmp -s small.vroc "$top/tests/shell/save_small.vroc"; then pass
else fail "the save file's text differs from tests/shell/save_small.vroc"; diff "$top/tests/shell/save_small.vroc" small.vroc | head -10; fi
# read and saved again: the same file (nothing lost, nothing added)
{ cat pile.vroc; echo "save again.vroc"; } | "$vroc" -q 2>again.err
if cmp -s pile.vroc again.vroc; then pass; else fail "a saved file read and saved again differs"; diff pile.vroc again.vroc | head -6; fi

echo "$passed passed, $failed failed"
[ "$failed" = 0 ]
