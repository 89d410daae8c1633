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
# a private network namespace), a track file playing with collision
# sounds (the reader's head, hand, sound log and rendered frames are the
# saving run's), and a live tracker (its samples saved, not its
# subscription).  Then the text format is pinned by a
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

# ---- a prism sliding off a floor's edge: the edit fuzzer's seed 6785, whose
# reader parted from the saving run at its 9th frame after the save (a walk
# 1e-11 m above the impact's level from one start and not from the other;
# src/contact.c, vrContact_Within)
sed "s#@DATA@#$top/tests/data#" "$top/tests/data/prism_edge_seed6785.cmd" >prism_edge.cmd
{ cat "$top/tests/data/prism_edge_seed6785.after"; echo stats; } >after.cmd
two_runs prism_edge 20 after.cmd
# and a run that never saves (whose walks keep their starts) dumps the same
{ cat prism_edge.cmd; echo "step 20"; cat after.cmd; } | "$vroc" -q 2>/dev/null | grep -v '^frames=' >prism_edge.s
if grep -v '^frames=' prism_edge.a | cmp -s - prism_edge.s; then pass; else fail "prism_edge: a run without the save differs"; fi

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

# ---- a track file playing, collision sounds, the view and its frames -----------
# Saved in the middle of a track file's play (the head walks and turns,
# the hand sweeps with its trigger down for a while) and between two
# impacts of a pair still refractory: after the save, the reader's `show
# head`/`show hand`, dump, stats, sound log and rendered frames (the head
# drives the view) are the saving run's, byte for byte.
awk 'BEGIN {
    print "# the head walks along x turning about z; the hand sweeps with its trigger"
    for (k = 0; k <= 40; k++) {
        t = k * 0.05; a = 0.3 * t; b = 0.7 * t
        printf "%.6f head %.6f -3 1.7 %.9f 0 0 %.9f\n", t, 0.4 * t, cos(a / 2), sin(a / 2)
        if (k % 2 == 0)
            printf "%.6f hand %.6f 0.5 %.6f %.9f %.9f 0 0 %d\n", t + 0.01, 0.3 * sin(t), 1 + 0.1 * t,
                cos(b / 2), sin(b / 2), (t > 0.4 && t < 1.2) ? 1 : 0
    }
}' >walk.trk
# a ball between two plates, 0.1 m of travel at 3 m/s: each plate is hit
# every 0.0667 s, so only every other hit sounds (0.1 s refractory)
cat >walk.cmd <<'S'
time_step = 0.05
collision_dist = 0.01
resolution = (48, 32)
cube lo
  size = (1, 1, 0.05)
  mass = -1
cube hi
  size = (1, 1, 0.05)
  translate = (0, 0, 0.4)
  mass = -1
sphere ball
  radius = 0.1
  translate = (0, 0, 0.2)
  linear_vel = (0.1, 0, 3)
  elasticity = 1
track walk.trk
S
walk_after() {   # $1: the output name (sound log, frames folder)
    printf '%s\n' "sound_log = $1.snd" "frames = $1.frames" "step 3" "show head" "show hand" "step 10" \
        "show head" "show hand" "dump" "stats"
}
# walk_run NAME INPUT...: a run of the saved state's continuation, its outputs kept as NAME.*
walk_run() {
    name=$1; shift
    { cat "$@"; walk_after "$name"; } | "$vroc" -q >"$name.out" 2>"$name.err"
    [ -s "$name.err" ] && { fail "$name: errors"; head -3 "$name.err"; }
    no_ms "$name.out" >"$name.cmp"
}
# walk_same A B: the outputs, the sound logs, every frame's bytes
walk_same() {
    if ! cmp -s "$1.cmp" "$2.cmp"; then fail "walk: $2 differs from $1 (dump, show)"; diff "$1.cmp" "$2.cmp" | head -4; return 1; fi
    if ! cmp -s "$1.snd" "$2.snd"; then fail "walk: $2's sound log differs from $1's"; diff "$1.snd" "$2.snd" | head -4; return 1; fi
    frames=$(ls "$1.frames" 2>/dev/null | wc -l)
    if [ "$frames" != 26 ]; then fail "walk: $1 rendered $frames frame files, not 26"; return 1; fi
    for f in "$1.frames"/*; do
        cmp -s "$f" "$2.frames/${f##*/}" || { fail "walk: $2's ${f##*/} differs from $1's"; return 1; }
    done
    return 0
}
{ cat walk.cmd; echo "sound_log = before.snd"; echo "step 7"; echo "save walk.vroc"; } >walk.a.in
walk_run walka walk.a.in
walk_run walkb walk.vroc
walk_same walka walkb && pass
# the case proves something only if the save holds both devices' samples
# and a pair still refractory whose next hit falls after the save
if grep -q '^state sample device=head ' walk.vroc && grep -q '^state sample device=hand .* buttons=1$' walk.vroc \
    && grep -q '^state sound_pair a=lo b=ball ' walk.vroc && [ "$(grep -c bounce walka.snd)" -ge 8 ]; then pass
else fail "walk: the save holds no samples of both devices or no refractory pair, or too few sounds"; fi
# without its sound_pair lines the reader sounds the hit the saving run
# kept quiet; without the samples it has no head: the lines are what
# carries the state (the test above can fail)
grep -v '^state sound_pair' walk.vroc >walk_nosound.vroc
walk_run walkc walk_nosound.vroc
if cmp -s walka.snd walkc.snd; then fail "walk: the sound log is the same without the sound_pair lines"; else pass; fi
grep -v '^state sample' walk.vroc >walk_notrack.vroc
walk_run walkd walk_notrack.vroc
if grep -q '^head none' walkd.out && ! cmp -s walka.frames/frame-000010-left.ppm walkd.frames/frame-000010-left.ppm
then pass; else fail "walk: without the samples the reader still had the head, or the same view"; fi
# the reader's head is where the track file's motion puts it: x = 0.4 t,
# turned 0.3 t about z (the samples' slerp keeps a steady turn exact)
if awk '/^head / { t = $2; x = $3; w = $6; z = $9; a = 0.3 * t / 2; n++
        if ((x - 0.4 * t)^2 > 1e-12 || (w - cos(a))^2 > 1e-16 || (z - sin(a))^2 > 1e-16) bad = 1 }
        END { exit !(n == 2 && !bad) }' walkb.out; then pass
else fail "walk: the reader's head is not the track file's"; grep '^head' walkb.out; fi
# the first hit after the save on lo would sound at 0.3757 without the
# refractory time (lo sounded at 0.3103): it does not, and the next does
if awk -F, '$1 !~ /^#/ && $6 < 0.1 { print $1; exit }' walka.snd | grep -q '^0.44'; then pass
else fail "walk: the hit on lo just after the save sounded, or the next did not"; head -3 walka.snd; fi
# a live tracker's samples are saved, its subscription is not
# (vroc-tracker plays walk.trk over multicast on loopback, in real time)
url='udpm://239.255.76.68:7668?ttl=0'
{ echo "trackers = $url"; cat walk.cmd | grep -v '^track '; echo "step 20"; echo "save mid.vroc"
  echo "show head"; echo "show hand"; echo "step 25"; echo "save end.vroc"; echo "step 5"
  echo "show head"; echo "show hand"; echo "dump"; } >livea.cmd
"$vroc" -q livea.cmd >livea.out 2>livea.err &
pid=$!
sleep 1
"${vroc%/vroc}/vroc-tracker" walk.trk "$url" >feed.out 2>&1 || fail "live: vroc-tracker failed: $(head -1 feed.out)"
wait $pid || fail "live: the listening vroc failed: $(head -1 livea.err)"
if grep -q '^# Live trackers (trackers = URL) were listened to' mid.vroc && ! grep -q '^trackers' mid.vroc \
    && [ "$(grep -c '^state sample device=head' mid.vroc)" -ge 1 ] && grep -q '^state sample device=hand' mid.vroc
then pass; else fail "live: the save holds no samples, no comment, or the subscription"; fi
{ cat mid.vroc; echo "show head"; echo "show hand"; } | "$vroc" -q >liveb.out 2>liveb.err
{ cat end.vroc; echo "step 5"; echo "show head"; echo "show hand"; echo "dump"; } | "$vroc" -q >livec.out 2>livec.err
head -2 livea.out >livea.mid; tail -n +3 livea.out >livea.end
if [ ! -s liveb.err ] && [ ! -s livec.err ] && grep -q '^head 1 ' livea.mid && cmp -s livea.mid liveb.out \
    && cmp -s livea.end livec.out; then pass
else fail "live: the reader's head, hand or bodies differ from the listening run's"
    diff livea.mid liveb.out | head -4; diff livea.end livec.out | head -4; head -2 liveb.err livec.err; fi

# ---- the tool panel, moved by the hand and held over the save ------------------
# The hand takes the sheet at its centre (0,-7,2.5) at 0.2 s and carries
# it 0.5 m along x and 0.3 m up by 1 s; saved at 0.5 s, the sheet held.
# The reader must hold it too (state panel, state grab, state sample) and
# leave it where the saving run does: show panel the same, and moved by
# the hand's displacement (stop's centre at x = -0.15 + 0.5).
cat >panel.trk <<'S'
0    hand 0 -7 2.5  1 0 0 0  0
0.2  hand 0 -7 2.5  1 0 0 0  1
1.0  hand 0.5 -7 2.8  1 0 0 0  1
1.2  hand 0.5 -7 2.8  1 0 0 0  0
S
cat >panel.cmd <<'S'
panel = 1
time_step = 0.1
sphere ball
translate = (0,0,1)
track panel.trk
S
after "step 10" "show panel" "dump" "stats"
two_runs panel 5 after.cmd
if grep -q '^state panel .*hold=3' panel.vroc && grep -q '^stop 0.35 ' panel.a; then pass
else fail "panel: no held sheet in the save, or the sheet did not follow the hand"; grep '^stop' panel.a; fi

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
