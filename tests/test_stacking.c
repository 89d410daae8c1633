/* test_stacking.c — the scenes a Box2D user builds first, in a world
 * (SPEC 7), each against physics: a pyramid and a tower that stand and
 * rest, three offset boxes that neither tip nor skate, dominoes that
 * topple, a ball that ends rolling at 5/7 of its speed, a box that holds
 * on a slope below atan mu and slides at g (sin - mu cos) above it (and is
 * not frozen as it sets off slowly), a ball rolling slower than rest_speed
 * that comes to rest and a faster one that rolls on, a
 * heavy box on light balls at the cost of a light one, an icosahedron that
 * tips onto a face, an elastic Newton's cradle that sends out one ball,
 * and a pile of a hundred that settles, none inside another, with the
 * energy never rising from one frame to the next (e < 1, friction).
 * (island.c's own tests take the solve alone: test_island.c.) */
#include <stdlib.h>
#include "test.h"
#include "vroc.h"
#include "vec.h"
#include "scene.h"

#define GC 1e-3                 /* the contact gap g_c: min(d, 1 mm) */
#define G 9.8

static void set_friction(vrObjectDef *d, const void *mu) { d->friction = *(const double *)mu; }

/* a box of half extents `half` at `at`, mass m (-1: static), elasticity e, friction mu */
static vrObjectId box(vrWorld *w, const char *name, vec3 half, vec3 at, double m, double e, double mu)
{
    vrObjectId id = vrScene_Box(w, name, half, at, m, e);
    if (id != VR_NO_OBJECT) vrScene_Edit(w, id, set_friction, &mu);
    return id;
}

static vrObjectId ball(vrWorld *w, const char *name, double r, vec3 at, vec3 v, double m, double e, double mu)
{
    vrObjectId id = vrScene_Sphere(w, name, r, at, v, m, e);
    if (id != VR_NO_OBJECT) vrScene_Edit(w, id, set_friction, &mu);
    return id;
}

/* the floor: a static slab whose top is z = 0 */
static vrObjectId floor_of(vrWorld *w, double mu) { return box(w, "floor", vec3_make(20, 20, 0.5), vec3_make(0, 0, -0.5), -1, 0, mu); }

static double energy(const vrWorld *w) { return vrScene_Stats(w).energy; }

/* n frames, the energy checked after each: never above the last by more
 * than SPEC 7 allows an event (1e-9 E + 1e-9 J) times the frame's events
 * (its island steps and the contacts answered); 0, or 1 and the frame
 * printed; `note`: the worst rise printed too */
static int steps_losing_energy_noting(vrWorld *w, int n, int note);
static int steps_losing_energy(vrWorld *w, int n) { return steps_losing_energy_noting(w, n, 0); }

static int steps_losing_energy_noting(vrWorld *w, int n, int note)
{
    const vrSettings *s = vrWorld_Settings(w);
    double e = energy(w), steps = ceil(s->time_step / s->contact_step - 1e-9);
    long long answered = vrScene_Stats(w).collisions;
    double worst = 0;
    int f;
    for (f = 0; f < n; f++) {
        double now, events;
        if (vrScene_Step(w, 1) != 0) return 1;
        now = energy(w);
        events = steps + (double)(vrScene_Stats(w).collisions - answered);
        if (now > e + events * (1e-9 * fabs(e) + 1e-9)) {
            printf("    frame %d: energy rose from %.12g to %.12g (%g events)\n", f + 1, e, now, events);
            return 1;
        }
        worst = vr_max(worst, (now - e) / (events * fabs(e) + 1e-300));
        e = now;
        answered = vrScene_Stats(w).collisions;
    }
    if (note) printf("    the energy rose by at most %.2g E an event in a frame\n", worst);
    return 0;
}

/* the body's up axis (its z) in the world */
static vec3 up_axis(const vrObjectState *s)
{
    quat q = quat_make(s->orientation[0], s->orientation[1], s->orientation[2], s->orientation[3]);
    return quat_rotate(q, vec3_make(0, 0, 1));
}

static int count_resting(const vrWorld *w, const vrObjectId *ids, int n)
{
    int i, k = 0;
    for (i = 0; i < n; i++) k += vrScene_State(w, ids[i]).state == VR_STATE_REST;
    return k;
}

/* ---- pyramids and towers -------------------------------------------------------- */

/* A pyramid of 0.5 m boxes, `base` on its lowest row, rows `gap` apart
 * (each box's centre above the last row's by 0.5 + gap); friction 0.6,
 * e = 0.  Returns the number of boxes (ids in id[]). */
static int pyramid(vrWorld *w, int base, double gap, vrObjectId *id)
{
    int row, k, n = 0;
    for (row = 0; row < base; row++)
        for (k = 0; k < base - row; k++) {
            char name[32];
            double x = (k - (base - row - 1) / 2.0) * 0.5, z = 0.25 + gap + row * (0.5 + gap);
            snprintf(name, sizeof name, "p%d_%d", row, k);
            id[n++] = box(w, name, vec3_make(0.25, 0.25, 0.25), vec3_make(x, 0, z), 1, 0, 0.6);
        }
    return n;
}

/* every box of the pyramid within `slack` of where it was put, down by no
 * more than the row's gaps closing, and level */
static int pyramid_stands(const vrWorld *w, int base, double gap, const vrObjectId *id, double slack)
{
    int row, k, n = 0;
    for (row = 0; row < base; row++)
        for (k = 0; k < base - row; k++, n++) {
            vrObjectState s = vrScene_State(w, id[n]);
            double x = (k - (base - row - 1) / 2.0) * 0.5, z = 0.25 + gap + row * (0.5 + gap);
            double lowest = 0.25 + row * 0.5;     /* every gap closed, no box inside another */
            ENSURE_MSG(fabs(s.position[0] - x) < slack && fabs(s.position[1]) < slack, "box %d_%d at x %.6f y %.6f",
                       row, k, s.position[0], s.position[1]);
            ENSURE_MSG(s.position[2] > lowest - 1e-6 && s.position[2] < z + slack, "box %d_%d at z %.6f (put at %.6f)",
                       row, k, s.position[2], z);
            ENSURE_MSG(fabs(up_axis(&s).z) > 1 - 1e-6, "box %d_%d tilted", row, k);
        }
    return 0;
}

/* 55 boxes placed exactly touching: the weight reaches the floor, nothing
 * falls through, nothing bounces, and every box rests */
static int test_a_pyramid_of_55_placed_touching_stands_and_rests(void)
{
    vrWorld *w = vrScene_World(0.05, 0.01, G);
    vrObjectId id[55];
    int n;
    floor_of(w, 0.6);
    n = pyramid(w, 10, 0, id);
    ENSURE(n == 55);
    ENSURE(steps_losing_energy(w, 100) == 0);
    ENSURE(pyramid_stands(w, 10, 0, id, 1e-3) == 0);
    ENSURE_MSG(count_resting(w, id, n) == n, "%d of %d rest", count_resting(w, id, n), n);
    printf("    5 s: %lld collisions, %lld island contacts\n", vrScene_Stats(w).collisions,
           vrScene_Stats(w).island_contacts);
    vrWorld_Destroy(w);
    return 0;
}

/* the same with 0.5 mm between the rows: each row drops onto the one below
 * and the pyramid stands */
static int test_a_pyramid_placed_with_small_gaps_stands_and_rests(void)
{
    vrWorld *w = vrScene_World(0.05, 0.01, G);
    vrObjectId id[55];
    int n;
    floor_of(w, 0.6);
    n = pyramid(w, 10, 5e-4, id);
    ENSURE(steps_losing_energy(w, 100) == 0);
    ENSURE(pyramid_stands(w, 10, 5e-4, id, 2e-3) == 0);
    ENSURE_MSG(count_resting(w, id, n) == n, "%d of %d rest", count_resting(w, id, n), n);
    vrWorld_Destroy(w);
    return 0;
}

/* ten boxes, each dropped 1 cm onto the last, 2 cm off-centre to either
 * side in turn: the tower stands, in order, g_c apart, and rests */
static int test_a_tower_of_ten_dropped_off_centre_stands_and_rests(void)
{
    vrWorld *w = vrScene_World(0.05, 0.01, G);
    vrObjectId id[10];
    int i;
    floor_of(w, 0.6);
    for (i = 0; i < 10; i++) {
        char name[16];
        snprintf(name, sizeof name, "t%d", i);
        id[i] = box(w, name, vec3_make(0.25, 0.25, 0.25), vec3_make(i % 2 ? 0.02 : -0.02, 0, 0.25 + 0.01 + i * 0.51), 1, 0, 0.6);
    }
    ENSURE(steps_losing_energy(w, 100) == 0);
    for (i = 0; i < 10; i++) {
        vrObjectState s = vrScene_State(w, id[i]);
        ENSURE_MSG(s.position[2] > 0.25 + i * 0.5 - 1e-6 && s.position[2] < 0.25 + i * 0.5 + (i + 1) * 2 * GC,
                   "box %d at z %.6f", i, s.position[2]);
        ENSURE_MSG(fabs(s.position[0] - (i % 2 ? 0.02 : -0.02)) < 1e-3, "box %d moved to x %.6f", i, s.position[0]);
        ENSURE(fabs(up_axis(&s).z) > 1 - 1e-6);
    }
    ENSURE_MSG(count_resting(w, id, 10) == 10, "%d of 10 rest", count_resting(w, id, 10));
    vrWorld_Destroy(w);
    return 0;
}

/* three boxes dropped onto each other with 10 cm offsets (each centre of
 * mass well inside its support): none tips, none slides */
static int test_three_boxes_offset_10_cm_neither_tip_nor_slide(void)
{
    vrWorld *w = vrScene_World(0.02, 0.01, G);
    vrObjectId id[3];
    int i;
    floor_of(w, 0.5);
    for (i = 0; i < 3; i++) {
        char name[16];
        snprintf(name, sizeof name, "b%d", i);
        id[i] = box(w, name, vec3_make(0.25, 0.25, 0.25), vec3_make(0.1 * i, 0, 0.25 + 0.05 + i * 0.55), 1, 0.2, 0.5);
    }
    ENSURE(steps_losing_energy(w, 200) == 0);
    for (i = 0; i < 3; i++) {
        vrObjectState s = vrScene_State(w, id[i]);
        ENSURE_MSG(fabs(s.position[0] - 0.1 * i) < 1e-2 && fabs(s.position[1]) < 1e-2, "box %d at x %.4f", i, s.position[0]);
        ENSURE_MSG(fabs(up_axis(&s).z) > cos(0.01), "box %d tipped", i);   /* landing, it may keep 0.5 degree */
        ENSURE(s.state == VR_STATE_REST);
    }
    vrWorld_Destroy(w);
    return 0;
}

/* ---- dominoes ---------------------------------------------------------------------------- */

/* Ten dominoes 1 m high, 0.1 m thick, 0.6 m apart; the first tipped: each
 * falls onto the next, the last lies flat, the energy falls, and the
 * dominoes turn about their feet instead of skating: each foot stays near
 * where it stood. */
static int test_dominoes_topple_one_after_another(void)
{
    vrWorld *w = vrScene_World(0.05, 0.01, G);
    vrObjectId id[10];
    double spin[3] = {0, 1.5, 0};
    int i;
    floor_of(w, 0.6);
    for (i = 0; i < 10; i++) {
        char name[16];
        snprintf(name, sizeof name, "d%d", i);
        id[i] = box(w, name, vec3_make(0.05, 0.25, 0.5), vec3_make(i * 0.6, 0, 0.5), 1, 0, 0.6);
    }
    vrScene_Edit(w, id[0], vrScene_SetSpin, spin);
    ENSURE(steps_losing_energy(w, 200) == 0);
    for (i = 0; i < 10; i++) {
        vrObjectState s = vrScene_State(w, id[i]);
        vec3 up = up_axis(&s);
        /* the domino's foot: its centre less half its height along its axis */
        double foot = s.position[0] - 0.5 * up.x;
        ENSURE_MSG(up.x > 0.7, "domino %d did not fall forward: up (%.3f %.3f %.3f)", i, up.x, up.y, up.z);
        ENSURE_MSG(fabs(foot - i * 0.6) < 0.1, "domino %d's foot skated to %.3f from %.3f", i, foot, i * 0.6);
        ENSURE(s.state == VR_STATE_REST);
    }
    {
        vrObjectState last = vrScene_State(w, id[9]);
        ENSURE_MSG(last.position[2] < 0.05 + 2 * GC + 1e-6 && last.position[2] > 0.05 - 1e-6, "the last at z %.6f",
                   last.position[2]);
    }
    vrWorld_Destroy(w);
    return 0;
}

/* A domino (4 x 20 x 40 cm, friction 0.5, e 0.3) standing on the floor,
 * set spinning at 2 rad/s about its long horizontal axis, rocks up onto
 * its edge: 0.027 J/kg of spin against the 0.98 J/kg a tip over needs
 * (its centre rises 1 mm from 0.2 m to |(0.02, 0.2)|).  It must fall back
 * and rest standing on its face: inside its tipping angle (5.7 degrees)
 * nothing holds it on its edge.  (It rocks from edge to edge, as a slender
 * block does (Housner 1963), and rests after 3.7 s.)  Rest that looked only
 * at its motion put it to rest at its first turning point, leaning 3.4
 * degrees. */
static int test_a_domino_rocked_onto_its_edge_falls_back_and_rests_standing(void)
{
    vrWorld *w = vrScene_World(0.01, 0.01, G);
    double spin[3] = {0, 2, 0};
    vrObjectId d;
    vrObjectState s;
    floor_of(w, 0.5);
    d = box(w, "domino", vec3_make(0.02, 0.1, 0.2), vec3_make(0, 0, 0.2 + GC), 1, 0.3, 0.5);
    vrScene_Edit(w, d, vrScene_SetSpin, spin);
    ENSURE(steps_losing_energy(w, 500) == 0);
    s = vrScene_State(w, d);
    ENSURE_MSG(s.state == VR_STATE_REST, "the domino does not rest after 5 s");
    ENSURE_MSG(up_axis(&s).z > cos(1e-3), "the domino rests leaning %.2f degrees", acos(up_axis(&s).z) * 57.29577951308232);
    vrWorld_Destroy(w);
    return 0;
}

/* ---- friction ------------------------------------------------------------------------------- */

/* A ball launched sliding at v0 on a floor with friction mu slides for
 * 2 v0 / (7 mu g), then rolls at 5/7 v0 with w = v / r, and loses nothing
 * more. */
static int test_a_launched_ball_ends_rolling_at_five_sevenths(void)
{
    vrWorld *w = vrScene_World(0.01, 0.01, G);
    double r = 0.1, v0 = 2, mu = 0.4, e_roll;
    vrObjectId b;
    vrObjectState s;
    floor_of(w, mu);
    b = ball(w, "ball", r, vec3_make(0, 0, r + GC), vec3_make(v0, 0, 0), 1, 0, mu);
    ENSURE(vrScene_Step(w, 30) == 0);                 /* 0.3 s: rolling from 2 v0 / (7 mu g) = 0.146 s */
    s = vrScene_State(w, b);
    ENSURE_NEAR(s.linear_vel[0], 5.0 / 7.0 * v0, 1e-6);
    ENSURE_NEAR(s.angular_vel[1] * r, s.linear_vel[0], 1e-6);
    ENSURE_NEAR(s.linear_vel[2], 0, 1e-9);
    ENSURE(s.position[2] > r - 1e-9 && s.position[2] < r + 2 * GC);
    e_roll = energy(w);
    ENSURE(vrScene_Step(w, 100) == 0);
    s = vrScene_State(w, b);
    ENSURE_NEAR(s.linear_vel[0], 5.0 / 7.0 * v0, 1e-6);     /* a rolling ball loses nothing */
    ENSURE_NEAR(energy(w), e_roll, 1e-9 * e_roll);
    vrWorld_Destroy(w);
    return 0;
}

/* A ball spinning about the vertical on a floor stops: its point contact
 * resists turning as a patch of 1 mm (the man page's PHYSICS), so its spin
 * falls at mu g r_p / (2/5 r^2) (the twist mu m g r_p against I = 2/5 m r^2),
 * to 0 and no further, and then it rests. */
static int test_a_ball_spinning_on_the_floor_stops(void)
{
    vrWorld *w = vrScene_World(0.01, 0.01, G);
    double r = 0.2, mu = 0.5, w0 = 0.5, rp = 1e-3, decel = mu * G * rp / (0.4 * r * r), spin[3] = {0, 0, 0};
    vrObjectId b;
    floor_of(w, mu);
    b = ball(w, "ball", r, vec3_make(0, 0, r + GC), vec3_zero(), 1, 0, mu);
    ENSURE(vrScene_Step(w, 10) == 0);                 /* settled on the floor, in its island */
    spin[2] = w0;
    vrScene_Edit(w, b, vrScene_SetSpin, spin);
    ENSURE(vrScene_Step(w, 50) == 0);
    spin[0] = vrScene_State(w, b).angular_vel[2];
    ENSURE(vrScene_Step(w, 50) == 0);                 /* 0.5 s more, in island steps throughout */
    printf("    spin falls %.9f rad/s in 0.5 s, a t = %.9f\n", spin[0] - vrScene_State(w, b).angular_vel[2],
           0.5 * decel);
    ENSURE_NEAR(spin[0] - vrScene_State(w, b).angular_vel[2], 0.5 * decel, 1e-9);
    ENSURE(vrScene_Step(w, 100) == 0);                /* stopped at w0 / a = 1.63 s */
    ENSURE_NEAR(vrScene_State(w, b).angular_vel[2], 0, 1e-12);
    ENSURE(vrScene_State(w, b).state == VR_STATE_REST);
    vrWorld_Destroy(w);
    return 0;
}

/* A ramp turned th about y: its top face through the origin, with normal
 * (-sin th, 0, cos th), going down toward -x along (-cos th, 0, -sin th). */
static vec3 ramp_normal(double th) { return vec3_make(-sin(th), 0, cos(th)); }
static vec3 downhill(double th) { return vec3_make(-cos(th), 0, -sin(th)); }

static vrObjectId ramp(vrWorld *w, double th, double mu)
{
    double rot[4] = {0, 1, 0, 0};
    vrObjectId id = box(w, "ramp", vec3_make(10, 2, 0.5), vec3_scale(ramp_normal(th), -0.5), -1, 0, mu);
    rot[3] = -th;
    vrScene_Edit(w, id, vrScene_SetRotation, rot);
    return id;
}

/* a box of half 0.1 on the ramp at the origin (g_c above it), turned with it */
static vrObjectId box_on_ramp(vrWorld *w, double th, double mu)
{
    double rot[4] = {0, 1, 0, 0};
    vrObjectId id = box(w, "box", vec3_make(0.1, 0.1, 0.1), vec3_scale(ramp_normal(th), 0.1 + GC), 1, 0, mu);
    rot[3] = -th;
    vrScene_Edit(w, id, vrScene_SetRotation, rot);
    return id;
}

/* how far the box went down the slope from where it was put */
static double down_slope(const vrObjectState *s, double th)
{
    vec3 x = vec3_make(s->position[0], s->position[1], s->position[2]);
    return vec3_dot(vec3_sub(x, vec3_scale(ramp_normal(th), 0.1 + GC)), downhill(th));
}

/* A box resting on a 10 degree ramp (mu 0.5), and a frictionless box
 * sliding up the ramp into it, arriving at 0.1 m/s (slower than v_rest: a
 * touch at an island step, not an impact); `heap_off`: the thesis's
 * ablation.  The resting box's id, or VR_NO_OBJECT. */
static vrObjectId woken_on_ramp(vrWorld *w, int heap_off)
{
    double th = 10 * VR_PI / 180, gap = 0.05, v0 = sqrt(0.01 + 2 * G * sin(th) * gap);
    double rot[4] = {0, 1, 0, 0}, v[3];
    vrObjectId a, b;
    if (heap_off) vrScene_Set(w, vrScene_HeapOff);
    ramp(w, th, 0.5);
    a = box_on_ramp(w, th, 0.5);
    if (a == VR_NO_OBJECT || vrScene_Step(w, 100) != 0) return VR_NO_OBJECT;
    b = box(w, "pusher", vec3_make(0.1, 0.1, 0.1),
            vec3_add(vec3_scale(ramp_normal(th), 0.1 + GC), vec3_scale(downhill(th), 0.2 + gap)), 1, 0.5, 0);
    if (b == VR_NO_OBJECT) return VR_NO_OBJECT;
    rot[3] = -th;
    v[0] = -downhill(th).x * v0, v[1] = 0, v[2] = -downhill(th).z * v0;
    vrScene_Edit(w, b, vrScene_SetRotation, rot);
    vrScene_Edit(w, b, vrScene_SetVelocity, v);
    return a;
}

/* The resting box, woken when the pusher touches it at an island step,
 * wakes with its island before the step is solved (SPEC 7: islands rest
 * and wake as one), its contact with the ramp gathered again and solved
 * with the touch (island_step.c).  Woken only after the solve, it took the
 * step's gravity with the ramp's contact left out, and the ramp answered
 * its corners one impulse at a time (pile seed 7 gained 4.7e-5 J so at
 * frame 505: test_piles_of_six_more_seeds_gain_no_energy).  The owner's
 * touching pairs, with the heap, left out a pair inside the envelope that
 * the wake had just scheduled, which heap = 0 looks at (pair_events.c):
 * heap on and off give the same bits, and the energy never rises. */
static int test_a_resting_box_woken_by_a_touch_wakes_with_its_support(void)
{
    vrWorld *w[2];
    vrObjectId a = VR_NO_OBJECT;
    int f, k, woke = 0;
    for (k = 0; k < 2; k++) {
        w[k] = vrScene_World(0.01, 0.01, G);
        a = woken_on_ramp(w[k], k);
        ENSURE(a != VR_NO_OBJECT);
    }
    ENSURE(vrScene_State(w[0], a).state == VR_STATE_REST);
    for (f = 0; f < 150; f++) {
        ENSURE(steps_losing_energy(w[0], 1) == 0);
        woke |= vrScene_State(w[0], a).state != VR_STATE_REST;
    }
    ENSURE(woke);
    ENSURE(vrScene_Step(w[1], 150) == 0);
    ENSURE(vrScene_SameDumps(w[0], w[1]));
    vrWorld_Destroy(w[0]);
    vrWorld_Destroy(w[1]);
    return 0;
}

/* On a 20 degree slope with mu 0.5 (atan mu = 26.6 degrees) the box holds;
 * on 30 degrees with mu 0.3 it slides at v = a t, a = g (sin - mu cos),
 * and s = a t^2 / 2 + a h t / 2: the island steps (h = time_step / 3 here)
 * are semi-implicit Euler's, whose distance runs that far ahead. */
static int test_a_box_holds_on_a_gentle_slope_and_slides_down_a_steep_one(void)
{
    double th = 20 * VR_PI / 180, t = 1.0;
    vrWorld *w = vrScene_World(0.01, 0.01, G);
    vrObjectId b;
    vrObjectState s;
    ramp(w, th, 0.5);
    b = box_on_ramp(w, th, 0.5);
    ENSURE(vrScene_Step(w, 100) == 0);
    s = vrScene_State(w, b);
    printf("    holds at 20 deg: moved %.3g m down the slope in 1 s\n", down_slope(&s, th));
    ENSURE_MSG(fabs(down_slope(&s, th)) < 1e-4, "crept %.3g m", down_slope(&s, th));
    vrWorld_Destroy(w);

    th = 30 * VR_PI / 180;
    w = vrScene_World(0.01, 0.01, G);
    ramp(w, th, 0.3);
    b = box_on_ramp(w, th, 0.3);
    ENSURE(vrScene_Step(w, 100) == 0);
    s = vrScene_State(w, b);
    {
        double a = G * (sin(th) - 0.3 * cos(th)), h = 0.01 / 3, want = 0.5 * a * t * t + 0.5 * a * h * t;
        printf("    slides at 30 deg: %.9f m in 1 s, a t^2 / 2 + a h t / 2 = %.9f\n", down_slope(&s, th), want);
        ENSURE_NEAR(down_slope(&s, th), want, 1e-6);
        ENSURE_NEAR(vec3_dot(vrScene_LinearVel(&s), downhill(th)), a * t, 1e-6);
    }
    vrWorld_Destroy(w);
    return 0;
}

/* A ball (r 0.1, mu 0.5) let go on a 20 degree slope rolls without
 * slipping (tan 20 = 0.36 < 7/2 mu): its centre's speed is a t with
 * a = 5/7 g sin, its spin v / r, and rolling does no work: the energy it
 * loses is only what the island steps' semi-implicit Euler costs, whose
 * distance runs a h t / 2 ahead (as the sliding box's above): m g sin
 * a h t / 2.  With mu 0.05 it slips instead, as Coulomb has it. */
static int test_a_ball_rolls_down_a_slope_at_five_sevenths_g_sin(void)
{
    double th = 20 * VR_PI / 180, t = 1.0, r = 0.1, a = 5.0 / 7.0 * G * sin(th), h = 0.01 / 3, e0, lost;
    vrWorld *w = vrScene_World(0.01, 0.01, G);
    vrObjectId b;
    vrObjectState s;
    vec3 v, om, x;
    ramp(w, th, 0.5);
    b = ball(w, "ball", r, vec3_scale(ramp_normal(th), r + GC), vec3_zero(), 1, 0, 0.5);
    e0 = energy(w);
    ENSURE(vrScene_Step(w, 100) == 0);
    s = vrScene_State(w, b);
    v = vrScene_LinearVel(&s), x = vrScene_Position(&s);
    om = vec3_make(s.angular_vel[0], s.angular_vel[1], s.angular_vel[2]);
    lost = G * sin(th) * a * h * t / 2;
    printf("    after 1 s: %.9f m/s down the slope (5/7 g sin t = %.9f), spin times r %.9f, %.9f J lost (%.9f)\n",
           vec3_dot(v, downhill(th)), a * t, vec3_len(om) * r, e0 - energy(w), lost);
    ENSURE_NEAR(vec3_dot(v, downhill(th)), a * t, 1e-6);
    ENSURE_NEAR(vec3_dot(v, ramp_normal(th)), 0, 1e-9);
    ENSURE_NEAR(vec3_len(om) * r, vec3_dot(v, downhill(th)), 1e-6);
    ENSURE_NEAR(vec3_dot(vec3_sub(x, vec3_scale(ramp_normal(th), r + GC)), downhill(th)), a * t * t / 2 + a * h * t / 2, 1e-6);
    ENSURE_NEAR(e0 - energy(w), lost, 1e-6);
    vrWorld_Destroy(w);

    /* mu 0.05 (tan 20 > 7/2 mu): it slips all the way, v = g (sin - mu cos) t
     * and w r = 5/2 mu g cos t (the friction's torque, mu m g cos r, over
     * 2/5 m r^2) */
    w = vrScene_World(0.01, 0.01, G);
    ramp(w, th, 0.05);
    b = ball(w, "ball", r, vec3_scale(ramp_normal(th), r + GC), vec3_zero(), 1, 0, 0.05);
    ENSURE(vrScene_Step(w, 100) == 0);
    s = vrScene_State(w, b);
    v = vrScene_LinearVel(&s);
    om = vec3_make(s.angular_vel[0], s.angular_vel[1], s.angular_vel[2]);
    printf("    mu 0.05: %.9f m/s (g (sin - mu cos) t = %.9f), spin times r %.9f (5/2 mu g cos t = %.9f)\n",
           vec3_dot(v, downhill(th)), G * (sin(th) - 0.05 * cos(th)) * t, vec3_len(om) * r, 2.5 * 0.05 * G * cos(th) * t);
    ENSURE_NEAR(vec3_dot(v, downhill(th)), G * (sin(th) - 0.05 * cos(th)) * t, 1e-6);
    ENSURE_NEAR(vec3_len(om) * r, 2.5 * 0.05 * G * cos(th) * t, 1e-6);
    vrWorld_Destroy(w);
    return 0;
}

/* A box on a 0.3 friction slope just past atan 0.3, accelerating at
 * a = 0.05 m/s^2 from rest: it gains 5e-6 m a frame, so each frame it is
 * still by SPEC 3.5's measure (under 1e-4 m) and slow; the rest test must
 * see that it speeds up (rest.c), or it is frozen where it was put.  It
 * slides at s = a t^2 / 2 + a h t / 2 as on the steep slope above. */
static int test_a_box_setting_off_slowly_down_a_slope_is_not_frozen(void)
{
    double mu = 0.3, a = 0.05, th = atan(mu) + asin(a / (G * sqrt(1 + mu * mu))), t = 2.0, h = 0.01 / 3;
    vrWorld *w = vrScene_World(0.01, 0.01, G);
    vrObjectId b;
    vrObjectState s;
    double want = 0.5 * a * t * t + 0.5 * a * h * t;
    ramp(w, th, mu);
    b = box_on_ramp(w, th, mu);
    ENSURE(vrScene_Step(w, 200) == 0);
    s = vrScene_State(w, b);
    printf("    slope %.4f deg: %.9f m in 2 s, a t^2 / 2 + a h t / 2 = %.9f; %s\n", th * 180 / VR_PI,
           down_slope(&s, th), want, s.state == VR_STATE_REST ? "resting" : "moving");
    ENSURE(s.state != VR_STATE_REST);
    ENSURE_NEAR(down_slope(&s, th), want, 1e-6);
    ENSURE_NEAR(vec3_dot(vrScene_LinearVel(&s), downhill(th)), a * t, 1e-6);
    vrWorld_Destroy(w);
    return 0;
}

static void still_rule_only(vrSettings *s) { s->rest_speed = 0; }

/* a ball of radius 0.1 rolling on the floor at v (w = v / r): the frame it
 * came to rest at (-1: none in `frames`; -2: a step failed), and where it
 * was then */
static int rolled_until_rest(double v, int frames, int still_only, double *x)
{
    vrWorld *w = vrScene_World(0.01, 0.01, G);
    double spin[3] = {0, 0, 0};
    vrObjectId b;
    int f, failed = 0;
    spin[1] = v / 0.1;
    if (still_only) vrScene_Set(w, still_rule_only);
    floor_of(w, 0.5);
    b = ball(w, "ball", 0.1, vec3_make(0, 0, 0.1 + GC), vec3_make(v, 0, 0), 1, 0, 0.5);
    vrScene_Edit(w, b, vrScene_SetSpin, spin);
    for (f = 1; f <= frames && !failed; f++) {
        failed = vrScene_Step(w, 1) != 0;
        *x = vrScene_State(w, b).position[0];
        if (vrScene_State(w, b).state == VR_STATE_REST) break;
    }
    vrWorld_Destroy(w);
    return failed ? -2 : f <= frames ? f : -1;
}

/* A ball rolling at 2 cm/s (2e-4 m a frame, never still by SPEC 3.5's
 * measure) comes to rest once it has been slower than rest_speed (5 cm/s)
 * for half a second, where rolling without loss took it (x = v t); with
 * rest_speed = 0 it rolls on, and so does one at 10 cm/s. */
static int test_a_slowly_rolling_ball_comes_to_rest_and_a_faster_one_rolls_on(void)
{
    double x = 0, x_still = 0, x_fast = 0;
    int rest = rolled_until_rest(0.02, 300, 0, &x), still = rolled_until_rest(0.02, 300, 1, &x_still);
    int fast = rolled_until_rest(0.1, 300, 0, &x_fast);
    printf("    2 cm/s: rests at frame %d, x %.9f (v t = %.9f); rest_speed 0: %d, x %.6f; 10 cm/s: %d, x %.6f\n", rest,
           x, 0.02 * rest * 0.01, still, x_still, fast, x_fast);
    ENSURE(rest >= 50 && rest <= 55);
    ENSURE_NEAR(x, 0.02 * rest * 0.01, 1e-9);
    ENSURE(still == -1 && fast == -1);
    ENSURE_NEAR(x_still, 0.02 * 3, 1e-9);
    ENSURE_NEAR(x_fast, 0.1 * 3, 1e-9);
    return 0;
}

/* ---- mass ratios -------------------------------------------------------------------------------- */

/* a box of mass m dropped 5 cm onto four 1 g balls; the island contacts
 * and collisions it took; the box's and a ball's heights in *zb, *zs */
static int box_on_balls(double m, long long *work, double *zb, double *zs)
{
    vrWorld *w = vrScene_World(0.05, 0.01, G);
    vrObjectId bx, b[4];
    int i;
    floor_of(w, 0.5);
    for (i = 0; i < 4; i++) {
        char name[16];
        snprintf(name, sizeof name, "b%d", i);
        b[i] = ball(w, name, 0.05, vec3_make(i % 2 ? 0.3 : -0.3, i / 2 ? 0.3 : -0.3, 0.05 + GC), vec3_zero(), 0.001, 0, 0.5);
    }
    bx = box(w, "box", vec3_make(0.5, 0.5, 0.1), vec3_make(0, 0, 0.1 + 2 * (0.05 + GC) + 0.05), m, 0, 0.5);
    if (steps_losing_energy(w, 80) != 0) return 1;
    *work = vrScene_Stats(w).collisions + vrScene_Stats(w).island_contacts;
    *zb = vrScene_State(w, bx).position[2];
    *zs = vrScene_State(w, b[0]).position[2];
    ENSURE(vrWorld_AllAtRest(w));
    vrWorld_Destroy(w);
    return 0;
}

/* A 1000 kg box on four 1 g balls (a ratio of 1e6) rests on them, none
 * pressed into the floor or the box, for the work a 1 kg box takes. */
static int test_a_heavy_box_rests_on_light_balls_at_the_cost_of_a_light_one(void)
{
    long long heavy, light;
    double zb, zs, zb1, zs1;
    ENSURE(box_on_balls(1000, &heavy, &zb, &zs) == 0);
    ENSURE(box_on_balls(1, &light, &zb1, &zs1) == 0);
    printf("    1000 kg box: %lld contacts answered, z %.6f; 1 kg box: %lld, z %.6f\n", heavy, zb, light, zb1);
    ENSURE_MSG(zs > 0.05 - 1e-6 && zs < 0.05 + 2 * GC, "a ball at z %.6f", zs);
    ENSURE_MSG(zb > 0.2 - 1e-6 && zb < 0.2 + 4 * GC, "the box at z %.6f", zb);
    ENSURE_MSG(heavy <= 2 * light + 100, "%lld against %lld", heavy, light);
    return 0;
}

/* ---- shapes ---------------------------------------------------------------------------------------- */

/* An icosahedron (edge 0.3 m) dropped onto a floor, turned, comes to rest
 * on a face: its centre at the inradius (within 2 g_c), three vertices
 * down. */
static int test_an_icosahedron_tips_onto_a_face(void)
{
    static const char *off_path = "build/ico-test.off";
    double p = (1 + sqrt(5.0)) / 2, s = 0.15, inradius = 2 * s * p * p / (2 * sqrt(3.0)), rot[4] = {1, 0.3, 0, 0.4};
    vrWorld *w = vrScene_World(0.05, 0.01, G);
    vrObjectDef d = vrObjectDef_Default(VR_POLYHEDRON);
    vrObjectId ico;
    vrObjectState st;
    FILE *f = fopen(off_path, "w");
    int a, b, c, down = 0;
    double v[12][3];
    ENSURE(f != NULL);
    for (a = 0; a < 12; a++) {           /* (0, +-1, +-p) cyclically, times s */
        double x[3] = {0, a % 2 ? 1 : -1, (a / 2) % 2 ? p : -p};
        int k = a / 4, j;
        for (j = 0; j < 3; j++) v[a][(j + k) % 3] = s * x[j];
    }
    fprintf(f, "OFF\n12 20 0\n");
    for (a = 0; a < 12; a++) fprintf(f, "%.17g %.17g %.17g\n", v[a][0], v[a][1], v[a][2]);
    for (a = 0; a < 12; a++)              /* the faces: the triples with every edge 2 s */
        for (b = a + 1; b < 12; b++)
            for (c = b + 1; c < 12; c++) {
                double ab = 0, bc = 0, ca = 0, nrm[3], out = 0;
                int j;
                for (j = 0; j < 3; j++) {
                    ab += (v[a][j] - v[b][j]) * (v[a][j] - v[b][j]);
                    bc += (v[b][j] - v[c][j]) * (v[b][j] - v[c][j]);
                    ca += (v[c][j] - v[a][j]) * (v[c][j] - v[a][j]);
                }
                if (fabs(ab - 4 * s * s) > 1e-9 || fabs(bc - 4 * s * s) > 1e-9 || fabs(ca - 4 * s * s) > 1e-9) continue;
                for (j = 0; j < 3; j++)
                    nrm[j] = (v[b][(j + 1) % 3] - v[a][(j + 1) % 3]) * (v[c][(j + 2) % 3] - v[a][(j + 2) % 3])
                           - (v[b][(j + 2) % 3] - v[a][(j + 2) % 3]) * (v[c][(j + 1) % 3] - v[a][(j + 1) % 3]);
                for (j = 0; j < 3; j++) out += nrm[j] * (v[a][j] + v[b][j] + v[c][j]);
                fprintf(f, "3 %d %d %d\n", a, out > 0 ? b : c, out > 0 ? c : b);
            }
    fclose(f);
    floor_of(w, 0.5);
    snprintf(d.file, sizeof d.file, "%s", off_path);
    d.translate[2] = 0.5;
    d.mass = 1, d.mass_set = 1, d.elasticity = 0.2, d.friction = 0.5;
    ico = vrScene_Add(w, "ico", VR_POLYHEDRON, &d);
    ENSURE(ico != VR_NO_OBJECT);
    vrScene_Edit(w, ico, vrScene_SetRotation, rot);
    ENSURE(steps_losing_energy(w, 200) == 0);
    st = vrScene_State(w, ico);
    ENSURE_MSG(st.position[2] > inradius - 1e-6 && st.position[2] < inradius + 2 * GC, "centre at z %.6f, inradius %.6f",
               st.position[2], inradius);
    {
        quat q = quat_make(st.orientation[0], st.orientation[1], st.orientation[2], st.orientation[3]);
        for (a = 0; a < 12; a++) {
            vec3 x = vec3_add(vec3_make(st.position[0], st.position[1], st.position[2]),
                              quat_rotate(q, vec3_make(v[a][0], v[a][1], v[a][2])));
            down += x.z < 2 * GC;
        }
    }
    ENSURE_MSG(down == 3, "%d vertices down", down);
    ENSURE(st.state == VR_STATE_REST);
    remove(off_path);
    vrWorld_Destroy(w);
    return 0;
}

/* ---- Newton's cradle ------------------------------------------------------------------------------ */

/* Five touching balls (g_c apart), e = 1, no friction, no gravity; a sixth
 * comes in at 1 m/s: the last goes out at 1 m/s and the rest stay, the
 * energy and momentum as they were (simultaneous solves must not smear it). */
static int test_an_elastic_newtons_cradle_sends_out_one_ball(void)
{
    vrWorld *w = vrScene_World(0.01, 0.01, 0);
    vrObjectId id[6];
    double e0;
    int i;
    for (i = 0; i < 5; i++) {
        char name[16];
        snprintf(name, sizeof name, "c%d", i);
        id[i] = ball(w, name, 0.1, vec3_make(i * (0.2 + GC), 0, 0), vec3_zero(), 1, 1, 0);
    }
    id[5] = ball(w, "striker", 0.1, vec3_make(-0.5, 0, 0), vec3_make(1, 0, 0), 1, 1, 0);
    e0 = energy(w);
    ENSURE(vrScene_Step(w, 100) == 0);
    ENSURE_NEAR(vrScene_State(w, id[4]).linear_vel[0], 1, 1e-9);
    for (i = 0; i < 4; i++) ENSURE_NEAR(vrScene_State(w, id[i]).linear_vel[0], 0, 1e-9);
    ENSURE_NEAR(vrScene_State(w, id[5]).linear_vel[0], 0, 1e-9);
    ENSURE_NEAR(energy(w), e0, 1e-9 * e0);
    vrWorld_Destroy(w);
    return 0;
}

/* ---- a pile --------------------------------------------------------------------------------------- */

static double room_side = 4;
static void pile_settings(vrSettings *s)
{
    s->default_friction = 0.5;
    s->default_elasticity = 0.5;
    s->room = room_side;
    s->max_linear = 8;            /* the shell's caps, as `vroc` runs it */
    s->max_angular = 4;
}

/* Fifty random balls and boxes in a 3 m room (friction 0.5, e 0.5)
 * settling under gravity: no frame's energy rises by more than SPEC 7's
 * 1e-9 E + 1e-9 J an event.  Its islands of 30 and more stop at their 32
 * sweeps short of the exact answer, with points pushed apart (an impulse
 * while separating) that lift bodies: the kinetic energy after the solve
 * was below the kinetic energy with the step's gravity in it, but the
 * flight at the new velocities climbed, and frame 399 rose 3.7e-6 J
 * (1.2e-8 E an event).  Now the step's energy is checked (island.h). */
static int test_a_settling_pile_of_fifty_gains_no_energy(void)
{
    vrWorld *w = vrScene_World(0.01, 0.01, G);
    char err[256];
    room_side = 3;
    vrScene_Set(w, pile_settings);
    room_side = 4;
    ENSURE(vrWorld_AddRandom(w, 50, err, sizeof err) == 0);
    ENSURE(steps_losing_energy_noting(w, 420, 1) == 0);
    printf("    %lld collisions, %lld island contacts in 420 frames\n", vrScene_Stats(w).collisions,
           vrScene_Stats(w).island_contacts);
    vrWorld_Destroy(w);
    return 0;
}

/* A hundred random balls and boxes (`random 100` in a 4 m room, friction
 * 0.5, e 0.5) dropped under gravity: the energy never rises by more than
 * SPEC 7's 1e-9 E + 1e-9 J an event (1.9e-9 E before the step's energy was
 * checked: see the pile of fifty above), and after 60 s at
 * least 95 rest (a ball spinning about the vertical no longer keeps its
 * island awake: point contacts twist against a 1 mm patch); started again from where they lie (every one
 * put there still), the world's start check finds none inside another. */
static int test_a_pile_of_a_hundred_settles(void)
{
    vrWorld *w = vrScene_World(0.01, 0.01, G), *again = vrScene_World(0.01, 0.01, G);
    vrObjectId ids[128];
    char err[256];
    int n, i, resting;
    vrScene_Set(w, pile_settings);
    ENSURE(vrWorld_AddRandom(w, 100, err, sizeof err) == 0);
    ENSURE(steps_losing_energy_noting(w, 6000, 1) == 0);
    resting = vrScene_Stats(w).resting;
    printf("    after 60 s: %d of 100 rest, %lld collisions\n", resting, vrScene_Stats(w).collisions);
    ENSURE(resting >= 95);
    n = vrWorld_ObjectList(w, ids, 128);
    for (i = 0; i < n; i++) {
        vrObjectDef d;
        vrObjectState s = vrScene_State(w, ids[i]);
        quat q = quat_make(s.orientation[0], s.orientation[1], s.orientation[2], s.orientation[3]);
        double sh = sqrt(q.x * q.x + q.y * q.y + q.z * q.z);
        ENSURE(vrWorld_GetObjectDef(w, ids[i], &d) == 0);
        d.translate[0] = s.position[0], d.translate[1] = s.position[1], d.translate[2] = s.position[2];
        d.rotate_set = sh > 0;
        d.rotate_angle = 2 * atan2(sh, q.w);
        d.rotate_axis[0] = sh > 0 ? q.x / sh : 0, d.rotate_axis[1] = sh > 0 ? q.y / sh : 0, d.rotate_axis[2] = sh > 0 ? q.z / sh : 1;
        d.linear_vel[0] = d.linear_vel[1] = d.linear_vel[2] = 0;
        d.angular_vel[0] = d.angular_vel[1] = d.angular_vel[2] = 0;
        ENSURE(vrScene_Add(again, vrWorld_ObjectName(w, ids[i]), d.type, &d) != VR_NO_OBJECT);
    }
    ENSURE_MSG(vrWorld_Start(again, err, sizeof err) == 0, "%s", err);
    vrWorld_Destroy(w);
    vrWorld_Destroy(again);
    return 0;
}

/* The same pile from six more seeds: no frame's energy rises (6 and 9
 * broke the rule at 6a904f7, before spins over their caps by rounding
 * alone were cut again; seed 0's pile above broke it until a push-out's
 * lift was paid from a ball's spin and then its speed, effect.c; seed 8
 * broke it at frame 1992 by 9.8e-4 J while an island solve stopped early
 * could leave a contact sinking, island.c STALL_LEFT; seed 7 at frame 505
 * by 4.7e-5 J while a resting body woken at an island step was solved
 * without its own contacts, island_step.c wake_touched; 96 at frame 507
 * and 13 at 735, by up to 1.9e-3 J, while an island solve stopped at its
 * cap had all its impulses scaled back to pay what it gained, its bodies
 * creeping into the floor, island.c MORE_SWEEPS).  Seeds 0-99 over 30 s
 * all keep it now. */
static int seed_now;
static void pile_seed(vrSettings *s)
{
    pile_settings(s);
    s->seed = (unsigned long long)seed_now;
}

static int test_piles_of_six_more_seeds_gain_no_energy(void)
{
    static const int seeds[] = {6, 9, 8, 7, 96, 13}, frames[] = {3000, 3000, 2000, 600, 600, 800};
    char err[256];
    int k;
    for (k = 0; k < 6; k++) {
        vrWorld *w = vrScene_World(0.01, 0.01, G);
        seed_now = seeds[k];
        vrScene_Set(w, pile_seed);
        ENSURE(vrWorld_AddRandom(w, 100, err, sizeof err) == 0);
        printf("    seed %d\n", seeds[k]);
        ENSURE(steps_losing_energy_noting(w, frames[k], 1) == 0);
        vrWorld_Destroy(w);
    }
    return 0;
}

/* A ball dropped on the raised side of a box that leans on the floor, one
 * edge 0.5 mm off and the other 1.5 mm (e = 0): the impact's follow-ups are
 * answered with the islands' contacts together, and that answer holds
 * every point of the box's touch with the floor that comes in, the edge
 * beyond g_c too.  Holding only the points within g_c left the raised edge
 * coming in, so the same contact was answered again at the instant, up to
 * 64 times: 130 answers in these 5 frames (a pile of 300 took 20 s for its
 * first second). */
static int test_a_ball_on_a_leaning_box_is_answered_at_once(void)
{
    vrWorld *w = vrScene_World(0.01, 0.01, G);
    double th = 1e-3 / 0.3, lean[4] = {1, 0, 0, th}, h = 0.15, low;
    vrObjectId b;
    vrObjectState s;
    quat q;
    floor_of(w, 0);
    b = box(w, "box", vec3_make(h, h, h), vec3_make(0, 0, 0.5 * GC + h * (cos(th) + sin(th))), 1, 0, 0);
    vrScene_Edit(w, b, vrScene_SetRotation, lean);
    ball(w, "ball", 0.05, vec3_make(0, 0.12, 0.36), vec3_make(0, 0, -3), 1, 0, 0);
    ENSURE(steps_losing_energy(w, 5) == 0);
    printf("    %lld contacts answered\n", vrScene_Stats(w).collisions);
    ENSURE(vrScene_Stats(w).collisions <= 16);
    s = vrScene_State(w, b);        /* on the floor, not in it: its lowest corner above z = 0 */
    q = quat_make(s.orientation[0], s.orientation[1], s.orientation[2], s.orientation[3]);
    low = s.position[2] - h * (fabs(quat_rotate(q, vec3_make(1, 0, 0)).z) + fabs(quat_rotate(q, vec3_make(0, 1, 0)).z)
                               + fabs(quat_rotate(q, vec3_make(0, 0, 1)).z));
    ENSURE_MSG(low > 0 && low < 2 * GC, "the box's lowest corner at %g m", low);
    vrWorld_Destroy(w);
    return 0;
}

static const vrTest tests[] = {
    TEST(test_a_pyramid_of_55_placed_touching_stands_and_rests),
    TEST(test_a_pyramid_placed_with_small_gaps_stands_and_rests),
    TEST(test_a_tower_of_ten_dropped_off_centre_stands_and_rests),
    TEST(test_three_boxes_offset_10_cm_neither_tip_nor_slide),
    TEST(test_dominoes_topple_one_after_another),
    TEST(test_a_domino_rocked_onto_its_edge_falls_back_and_rests_standing),
    TEST(test_a_launched_ball_ends_rolling_at_five_sevenths),
    TEST(test_a_ball_spinning_on_the_floor_stops),
    TEST(test_a_box_holds_on_a_gentle_slope_and_slides_down_a_steep_one),
    TEST(test_a_ball_rolls_down_a_slope_at_five_sevenths_g_sin),
    TEST(test_a_resting_box_woken_by_a_touch_wakes_with_its_support),
    TEST(test_a_box_setting_off_slowly_down_a_slope_is_not_frozen),
    TEST(test_a_slowly_rolling_ball_comes_to_rest_and_a_faster_one_rolls_on),
    TEST(test_a_heavy_box_rests_on_light_balls_at_the_cost_of_a_light_one),
    TEST(test_an_icosahedron_tips_onto_a_face),
    TEST(test_an_elastic_newtons_cradle_sends_out_one_ball),
    TEST(test_a_ball_on_a_leaning_box_is_answered_at_once),
    TEST(test_a_settling_pile_of_fifty_gains_no_energy),
    TEST(test_a_pile_of_a_hundred_settles),
    TEST(test_piles_of_six_more_seeds_gain_no_energy),
};

const vrTestSuite vrSuite_Stacking = {"stacking", tests, TEST_COUNT(tests), NULL, NULL, 0};
