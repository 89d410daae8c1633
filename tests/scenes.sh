#!/bin/sh
# tests/scenes.sh — the thesis's environments, scenes/*.cmd (issue 7).
#
# Each scene is read as a user would (`read scenes/NAME.cmd`), with
# `max_frames = 0` first so that its closing `start` runs no frame, then
# stepped here, `dump` every few frames.  The checks:
#   - it loads and runs with no error and no note (stderr empty, status 0),
#     read so and as `vroc scenes/NAME.cmd` (its own `start` to the end);
#   - `stats` at frame 0 gives the objects, dynamic objects, pairs and
#     subframes_thesis of thesis table 5.1 (random: N(N-1)/2 + 6N pairs);
#   - at every dump, no dynamic object is inside a static one or below the
#     floor (z = 0 in every scene): the distance from its centre to each
#     static object (from `show` and `dump`) is at least its inner radius;
#   - its story, from the dumps: simple's balls rest on the table top,
#     desks' objects land and rest on the workstations and the table,
#     basketball's throw reaches the rim, bounces back and off the floor,
#     office's cuboid ends on the table (not on the shelf) and has knocked
#     table objects off, bounce's balls are hit and settle again on the chair
#     and the pedestal, random's objects stay in the room with their energy,
#     throw's tracked hand lands the ball in the basket;
#   - with heap = 0 every scene gives the same bits after 150 frames.
# VROC_SCENES=DIR reads the scenes from DIR instead of scenes/ (to see a
# check fail on a broken copy).  Run from the repository root with
# VROC_BUILD=<folder with vroc>; ends with `N passed, M failed`.
set -u
top=$(pwd)
case ${VROC_BUILD:?set VROC_BUILD to the build folder} in
/*) build=$VROC_BUILD ;;
*) build=$top/$VROC_BUILD ;;
esac
vroc=$build/vroc
scenes=${VROC_SCENES:-$top/scenes}
case $scenes in /*) ;; *) scenes=$top/$scenes ;; esac
passed=0 failed=0
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
export LSAN_OPTIONS="${LSAN_OPTIONS:-suppressions=$top/tests/lsan.supp:print_suppressions=0}"
export HOME="$tmp"        # never touch the real history

pass() { passed=$((passed + 1)); }
fail() { echo "FAIL $*"; failed=$((failed + 1)); }
# same_bits NAME A B: the two runs' outputs exist and are byte for byte the same
same_bits() {
    if [ -s "$2" ] && cmp -s "$2" "$3"; then pass
    else fail "$1"; diff "$2" "$3" | head -5; fi
}

if [ ! -x "$vroc" ]; then
    fail "scenes: no vroc in $build"
    echo "$passed passed, $failed failed"
    exit 1
fi

# run SCENE FRAMES EVERY: reads SCENE, prints stats, `show`s every object,
# then dumps at frame 0 and every EVERY frames up to FRAMES, then stats.
# Output in $tmp/SCENE.out, stderr in $tmp/SCENE.err, status in $st.
run() {
    f=$scenes/$1.cmd
    printf 'max_frames = 0\nread %s\ndump\n' "$f" | timeout 300 "$vroc" -q 2>/dev/null |
        awk -F, '!/^#/ { print $1 }' >"$tmp/$1.names"
    {
        printf 'max_frames = 0\nread %s\nstats\n' "$f"
        sed 's/^/show /' "$tmp/$1.names"
        echo dump
        n=0
        while [ $n -lt "$2" ]; do echo "step $3"; echo dump; n=$((n + $3)); done
        echo stats
    } >"$tmp/$1.in"
    timeout 300 "$vroc" <"$tmp/$1.in" >"$tmp/$1.out" 2>"$tmp/$1.err"
    st=$?
}

# the awk functions shared by the checks below: `show` blocks into
# type/mass/size of each object, dump lines into poses
lib='
function vec(s, v) { gsub(/[() ]/, "", s); split(s, v, ","); }
function show_line() {
    if ($1 == "name") { cur = $3; return 1 }
    if ($1 == "type") type[cur] = $3
    else if ($1 == "mass") mass[cur] = $3
    else if ($1 == "radius") rad[cur] = $3
    else if ($1 == "size") { vec($3 $4 $5, v); sx[cur] = v[1]; sy[cur] = v[2]; sz[cur] = v[3] }
    else if ($1 == "a1") sx[cur] = $3
    else if ($1 == "a2") sy[cur] = $3
    else if ($1 == "a3") sz[cur] = $3
    else if ($1 == "exp1") e1[cur] = $3
    else if ($1 == "exp2") e2[cur] = $3
    else return 0
    return 1
}
function min3(a, b, c) { return a < b ? (a < c ? a : c) : (b < c ? b : c) }
# the radius of a ball about the centre that lies inside the object
function inradius(o) {
    if (type[o] == "sphere") return rad[o]
    if (type[o] == "cube") return min3(sx[o], sy[o], sz[o])
    if (type[o] == "superquadric")   # the hull of a 10x10 sampling: 0.8 of the radii is inside
        return (e1[o] <= 1 && e2[o] <= 1 ? 0.8 : 0.8 / sqrt(3)) * min3(sx[o], sy[o], sz[o])
    return 0
}
# p (px,py,pz) into the frame of static object s at pose c, q
function local(s) {
    x = px - X[s]; y = py - Y[s]; z = pz - Z[s]
    qx = -QX[s]; qy = -QY[s]; qz = -QZ[s]; qw = QW[s]
    tx = 2 * (qy * z - qz * y); ty = 2 * (qz * x - qx * z); tz = 2 * (qx * y - qy * x)
    lx = x + qw * tx + (qy * tz - qz * ty)
    ly = y + qw * ty + (qz * tx - qx * tz)
    lz = z + qw * tz + (qx * ty - qy * tx)
}
function pos(a) { return a > 0 ? a : 0 }
function abs(a) { return a < 0 ? -a : a }
# distance from (px,py,pz) to static object s; < 0 inside.  For a
# superquadric, the distance along the ray from its centre (not less than
# the true distance)
function dist(s,   dx, dy, dz, F) {
    local(s)
    if (type[s] == "sphere") return sqrt(lx * lx + ly * ly + lz * lz) - rad[s]
    if (type[s] == "cube") {
        if (abs(lx) < sx[s] && abs(ly) < sy[s] && abs(lz) < sz[s]) return -1
        dx = pos(abs(lx) - sx[s]); dy = pos(abs(ly) - sy[s]); dz = pos(abs(lz) - sz[s])
        return sqrt(dx * dx + dy * dy + dz * dz)
    }
    if (type[s] == "superquadric") {
        F = ((abs(lx) / sx[s]) ^ (2 / e2[s]) + (abs(ly) / sy[s]) ^ (2 / e2[s])) ^ (e2[s] / e1[s]) + (abs(lz) / sz[s]) ^ (2 / e1[s])
        if (F < 1) return -1
        return sqrt(lx * lx + ly * ly + lz * lz) * (1 - F ^ (-e1[s] / 2))
    }
    return 1e9
}
'

# from_the_command_line SCENE: `vroc scenes/SCENE.cmd`, as the README says,
# runs its story to the end: status 0, nothing printed (no error, no note)
from_the_command_line() {
    timeout 300 "$vroc" "$scenes/$1.cmd" </dev/null >"$tmp/$1.user" 2>&1
    s=$?
    if [ $s = 0 ] && [ ! -s "$tmp/$1.user" ]; then pass
    else fail "${1}_runs_from_the_command_line: vroc $1.cmd gave status $s and: $(head -c 300 "$tmp/$1.user")"; fi
}

# counts SCENE OBJECTS DYNAMIC PAIRS SUBFRAMES_THESIS: the first stats line
counts() {
    got=$(awk '/^frames=/ { for (i = 1; i <= NF; i++) { split($i, kv, "="); s[kv[1]] = kv[2] }
                            print s["objects"], s["dynamic"], s["pairs"], s["subframes_thesis"]; exit }' "$tmp/$1.out")
    if [ "$got" = "$2 $3 $4 $5" ]; then pass
    else fail "${1}_has_the_counts_of_table_5_1: objects dynamic pairs subframes_thesis = '$got', expected '$2 $3 $4 $5'"; fi
}

# loads SCENE: ran with status 0 and nothing on stderr (no error, no note)
loads() {
    if [ "$st" = 0 ] && [ ! -s "$tmp/$1.err" ]; then pass
    else fail "${1}_loads_and_runs_cleanly: status $st, stderr: $(head -c 300 "$tmp/$1.err")"; fi
}

# never_inside SCENE: at every dump, each dynamic object's centre is at
# least its inner radius (less 1e-6 m) from every static object and above
# the floor z = 0
never_inside() {
    msg=$(awk -F'[,]' "$lib"'
        /^name = / || /^[a-z0-9_]+ = / { FS = " "; $0 = $0; show_line(); FS = ","; next }
        /^#/ { next }
        NF == 16 && $16 == "static" { X[$1] = $3; Y[$1] = $4; Z[$1] = $5; QW[$1] = $6; QX[$1] = $7; QY[$1] = $8; QZ[$1] = $9; st[$1] = 1; next }
        NF == 16 {
            px = $3; py = $4; pz = $5; r = inradius($1); dumps[$2] = 1
            if (pz - r < -1e-6 && !bad) bad = sprintf("%s below the floor at t=%s (z=%s)", $1, $2, pz)
            for (s in st) { d = dist(s); if (d < r - 1e-6 && !bad) bad = sprintf("%s inside %s at t=%s (centre %g m from it, inner radius %g)", $1, s, $2, d, r) }
        }
        END { n = 0; for (t in dumps) n++; if (n < 2) bad = "no dumps"; print bad }' "$tmp/$1.out")
    if [ -z "$msg" ]; then pass; else fail "${1}_nothing_inside_a_static_object_or_below_the_floor: $msg"; fi
}

# story SCENE NAME AWK-PROGRAM: the program sees every dump line (fields
# split at commas: $1 name, $2 t, $3..$5 position, $10..$12 velocity, $16
# state); first[] and fin[] hold each object's first and final dump line.
# It prints nothing when the story holds, else why not.
story() {
    msg=$(awk -F, '
        NF == 16 && $1 !~ /^#/ { if (!($1 in first)) first[$1] = $0; fin[$1] = $0; t = $2 }
        '"$3"'' "$tmp/$1.out")
    if [ -z "$msg" ]; then pass; else fail "${2}: $msg"; fi
}

# ---- simple: three balls bounce on a table top and rest on it -------------------
run simple 400 10
loads simple
from_the_command_line simple
counts simple 4 3 6 6
never_inside simple
story simple simple_balls_rest_on_the_table_top '
    END { n = 0
        for (o in fin) { split(fin[o], f, ","); if (f[16] == "static") continue
            n++; h = f[5] - 0.76                 # table top at z = 0.76, 1.6 x 1.0 m
            if (f[16] != "rest" || f[3] < -0.8 || f[3] > 0.8 || f[4] < -0.5 || f[4] > 0.5 || h < 0.06 || h > 0.15)
                { printf "%s not resting on the table top: %s\n", o, fin[o]; exit } }
        if (n != 3) print n " balls" }'

# ---- desks: twelve objects fall onto the workstations and the table -----------
run desks 1000 20
loads desks
from_the_command_line desks
counts desks 43 12 438 2
never_inside desks
story desks desks_objects_land_and_rest_on_the_workstations_and_table '
    END { n = 0
        for (o in fin) { split(fin[o], f, ","); split(first[o], g, ","); if (f[16] == "static") continue
            n++                                  # table top: x -2.2..1.8, y 0..0.8, z 0.76
            if (f[16] != "rest") { printf "%s does not rest: %s\n", o, fin[o]; exit }
            if (f[3] < -2.2 || f[3] > 1.8 || f[4] < 0 || f[4] > 0.8 || f[5] < 0.76) { printf "%s not on the table or a workstation: %s\n", o, fin[o]; exit }
            if (g[5] - f[5] < 0.2) { printf "%s did not fall: from z=%s to z=%s\n", o, g[5], f[5]; exit } }
        if (n != 12) print n " dynamic objects" }'

# ---- basketball: the throw reaches the rim, bounces back, bounces on the floor ----
run basketball 300 2
loads basketball
from_the_command_line basketball
counts basketball 9 1 8 58
never_inside basketball
story basketball basketball_throw_hits_the_basket_and_bounces_on_the_floor '
    $1 == "ball" { dx = $3 - 12.425; dz = $5 - 3.05; d = sqrt(dx * dx + $4 * $4 + dz * dz)
        if (d < near) near = d
        if (near < 0.3 && $10 < 0) back = 1               # turned back at the basket
        if (back && $5 < 1 && $12 > 0) floor = 1 }        # then up again off the floor
    BEGIN { near = 1e9 }
    END { if (near >= 0.3) printf "the ball never came within 0.3 m of the rim centre (closest %g)\n", near
          else if (!back) print "the ball did not bounce back from the basket"
          else if (!floor) print "the ball did not bounce on the floor" }'

# ---- throw: a tracked hand takes the ball from the table into the basket -------
# (SPEC 8's select mode; the scene's own `step 150` plays its track file:
# the ball starts on the table at x = 0.2, the basket's walls stand at
# x = 1.74 and 2.26, |y| < 0.25, 0.3 m high)
run throw 60 10
loads throw
from_the_command_line throw
never_inside throw
story throw throw_ball_lands_in_the_basket '
    END { split(fin["ball"], b, ",")
          if (!(b[3] > 1.75 && b[3] < 2.25 && b[4] > -0.24 && b[4] < 0.24 && b[5] < 0.3))
              print "the ball is not in the basket: " fin["ball"]
          else if (b[16] == "moving") print "the ball still moves in the basket: " fin["ball"] }'

# ---- office: the cuboid is knocked off the shelf onto the table ----------------
run office 600 20
loads office
from_the_command_line office
counts office 43 8 308 12
never_inside office
story office office_cuboid_falls_from_the_shelf_onto_the_table '
    # table top: x -1.68..0.32, y 1.2..2.0, top surface z = 0.75; frictionless (the thesis
    # world), the cuboid may slide on and off it later: it lands on it
    $1 == "cuboid" && $3 > -1.68 && $3 < 0.32 && $4 > 1.2 && $4 < 2.0 && $5 > 0.75 && $5 < 1.1 && $16 != "moving" { landed = 1 }
    END { split(first["cuboid"], g, ",")
        if (g[5] < 1.8) { print "the cuboid does not start on the shelf top (z=" g[5] ")"; exit }
        if (!landed) { print "the cuboid never lay on the table: " fin["cuboid"]; exit }
        off = 0
        split("mug orange block vase book apple", on, " ")
        for (i = 1; i <= 6; i++) { split(fin[on[i]], f, ","); if (f[5] < 0.7) off++ }
        if (off < 2) print off " of the table objects knocked off the table, expected at least 2" }'

# ---- bounce: the pillows hit the balls, which settle on the chair and pedestal ----
run bounce 1100 20
loads bounce
from_the_command_line bounce
counts bounce 35 12 342 6
never_inside bounce
story bounce bounce_balls_settle_again_on_the_chair_and_pedestal '
    END { n = 0; moved = 0
        for (o in fin) { if (o !~ /^ball/) continue
            split(fin[o], f, ","); split(first[o], g, ","); n++
            # resting, or lying on the seat or the tray sliding (frictionless) slower than 2 cm/s,
            # after 11 s: only the rails stop a ball sliding a few cm/s, and one may cross
            # the seat for seconds (4 cm/s at 6 s since the answers at an instant hold
            # every point of a touch, 2026-12-06; all rest at 10.3 s since small bounces
            # are exact, 2026-12-07, and at 10.8 s since a ball striking a body that lies on
            # something is answered with its islands, 2026-12-07)
            if (f[16] != "rest" && !(f[16] == "supported" && f[10] * f[10] + f[11] * f[11] + f[12] * f[12] < 4e-4))
                { printf "%s does not lie still: %s\n", o, fin[o]; exit }
            # chair seat: x -0.75..-0.25, y 0.25..0.75, top z 0.45; tray: x 0.48..0.92, y 0.28..0.72, z 0.9
            chair = f[3] > -0.75 && f[3] < -0.25 && f[4] > 0.25 && f[4] < 0.75 && f[5] > 0.45 && f[5] < 0.55
            tray = f[3] > 0.48 && f[3] < 0.92 && f[4] > 0.28 && f[4] < 0.72 && f[5] > 0.9 && f[5] < 1
            if (!chair && !tray) { printf "%s is not on the chair or the pedestal: %s\n", o, fin[o]; exit }
            dx = f[3] - g[3]; dy = f[4] - g[4]; if (dx * dx + dy * dy > 1e-4) moved++ }
        if (n != 10) print n " balls"
        else if (moved < 4) print "only " moved " balls were moved by the pillows" }'

# ---- random: 40 objects in a 10 m room keep their energy and stay in ---------------
run random 200 20
loads random
from_the_command_line random
counts random 46 40 1020 160
never_inside random
msg=$(awk '/^frames=/ { for (i = 1; i <= NF; i++) { split($i, kv, "="); s[kv[1]] = kv[2] }
                        if (!e0) { e0 = s["energy"]; next } e1 = s["energy"]; c = s["collisions"] }
           END { d = (e1 - e0) / e0; if (d < 0) d = -d
                 if (c < 50) print "only " c " collisions in 200 frames"
                 else if (d > 1e-6) print "energy " e0 " became " e1 }' "$tmp/random.out")
if [ -z "$msg" ]; then pass; else fail "random_objects_collide_and_keep_their_energy: $msg"; fi

# ---- every scene: heap = 0 (every pair, every internal step) gives the same bits ----
# SPEC 3.2: the heap and the broadphase only skip looks that cannot matter
for sc in simple desks basketball office bounce random; do
    {
        printf 'max_frames = 0\nread %s\n' "$scenes/$sc.cmd"
        echo "step 150"; echo dump
    } | timeout 300 "$vroc" -q >"$tmp/$sc.heap1" 2>&1
    {
        printf 'max_frames = 0\nread %s\nheap = 0\n' "$scenes/$sc.cmd"
        echo "step 150"; echo dump
    } | timeout 600 "$vroc" -q >"$tmp/$sc.heap0" 2>&1
    same_bits "${sc}_heap_on_and_off_give_the_same_bits" "$tmp/$sc.heap1" "$tmp/$sc.heap0"
done

# ---- a crowded room: several impacts in one internal step ----
# 30 bodies thrown about a 3 m room under gravity: at many grid points an
# impact is found and others are looked at around it (bisect.c: bisections past
# it stop, and the keys found there are dropped, as they are rolled back); some
# of those looks find an earlier impact, which must win as it does when
# every pair is looked at in index order (heap = 0)
crowd='time_step = 0.05
collision_dist = 0.01
max_linear = 16
max_angular = 100
gravity
seed = 3
room = 3
random 30
step 30
dump'
printf '%s\n' "$crowd" | timeout 300 "$vroc" -q >"$tmp/crowd.heap1" 2>&1
printf 'heap = 0\n%s\n' "$crowd" | timeout 600 "$vroc" -q >"$tmp/crowd.heap0" 2>&1
same_bits a_crowded_room_gives_the_same_bits_heap_on_and_off "$tmp/crowd.heap1" "$tmp/crowd.heap0"

# ---- many responses at one instant: ties with a bisection's own start ----
# past the 64 responses an instant, a bisection's event can be its bracket's
# untested lower end, the instant of an event already found: a tie that pair
# order decides, not a later event (a bisection stopped there once: heap on
# and off parted)
data=$top/tests/data
timeout 300 "$vroc" -q "$data/instant_chatter.cmd" >"$tmp/chatter.heap1" 2>&1
{ echo "heap = 0"; cat "$data/instant_chatter.cmd"; } | timeout 300 "$vroc" -q >"$tmp/chatter.heap0" 2>&1
same_bits a_chattering_instant_gives_the_same_bits_heap_on_and_off "$tmp/chatter.heap1" "$tmp/chatter.heap0"

# ---- answers that creep a rounding of t at a time end their frame ----
# a light table between the floor and a ball: each answer (taken back and
# answered with its islands) left the other pair coming in one rounding of
# t later, a new instant each time, and frame 115 never ended (the edit
# fuzzer's seed 531); after VR_INSTANT_MAX such answers the owners move on
# to the next grid point (src/owner.h vrInstant_Span).  The run takes
# 0.04 s; heap on and off agree.
timeout 60 "$vroc" -q "$data/creep_seed531.cmd" >"$tmp/creep.heap1" 2>&1
rc=$?
if [ "$rc" = 0 ] && grep -q '^table,' "$tmp/creep.heap1"; then pass; else fail "creeping_answers_end_their_frame: exit $rc"; fi
{ echo "heap = 0"; cat "$data/creep_seed531.cmd"; } | timeout 60 "$vroc" -q >"$tmp/creep.heap0" 2>&1
same_bits creeping_answers_give_the_same_bits_heap_on_and_off "$tmp/creep.heap1" "$tmp/creep.heap0"

# ---- near-parallel edges side by side are measured as edges ----
# two boxes, an upright edge of each facing the other, one turned 2e-8
# rad: the top vertex alone measured 9 cm for 1.9 cm, the heap put the
# pair off for 144 s and heap = 0 found the impact (the physics fuzzer's
# seed 10473); the dumps, not the stats (checks differ by design)
"$vroc" -q "$data/edges_side_by_side_seed10473.cmd" 2>&1 | grep -v '^frames=' >"$tmp/edges.heap1"
{ echo "heap = 0"; cat "$data/edges_side_by_side_seed10473.cmd"; } | "$vroc" -q 2>&1 | grep -v '^frames=' >"$tmp/edges.heap0"
same_bits edges_side_by_side_give_the_same_bits_heap_on_and_off "$tmp/edges.heap1" "$tmp/edges.heap0"

echo "$passed passed, $failed failed"
[ "$failed" = 0 ]
