/* test_clamps.c — SPEC 3.2's speed caps cut a speed once (stats clamps):
 * a body the cap cut is at the cap, and nothing that leaves its spin alone
 * (an island step holding it on a frictionless floor) cuts or counts it
 * again; the energy the cut left is kept.
 *
 *   ball            — a ball of 1 kg, 10 cm, on the floor at its centre's height
 *   set_friction    — vrScene_Edit's editor for an object's friction
 *   spin_of         — an object's |omega| and omega now
 *   holds_its_spin  — n frames in which no clamp is counted and each ball's
 *                     spin keeps its vector, at most the cap, and the
 *                     world's energy stays put
 */
#include "test.h"
#include "vroc.h"
#include "vec.h"
#include "scene.h"

#define R 0.1
#define CAP 4.0   /* vrScene_ShellCaps's max_angular */

static vrObjectId ball(vrWorld *w, const char *name, double x, double y, vec3 v)
{
    return vrScene_Sphere(w, name, R, vec3_make(x, y, R), v, 1, 0.5);
}

static void set_friction(vrObjectDef *d, const void *mu) { d->friction = *(const double *)mu; }

static vec3 spin_of(const vrWorld *w, vrObjectId id)
{
    vrObjectState s = vrScene_State(w, id);
    return vec3_make(s.angular_vel[0], s.angular_vel[1], s.angular_vel[2]);
}

/* A ball on a frictionless floor feels only normal impulses, through its
 * centre: its spin is the same vector at every frame, and the energy
 * (spin, slide, height) can only fall (the floor's e < 1 takes what speed
 * into it an impact left).  So from now on no cut may bite and none may
 * be counted; no frame may end above the start by 1e-9 E. */
static int holds_its_spin(vrWorld *w, const vrObjectId *id, int n_ids, int frames)
{
    vec3 w0[2];
    double e0 = vrScene_Stats(w).energy, worst = -INFINITY;
    long long clamps = vrScene_Stats(w).clamps;
    int f, i;
    for (i = 0; i < n_ids; i++) w0[i] = spin_of(w, id[i]);
    for (f = 0; f < frames; f++) {
        ENSURE(vrScene_Step(w, 1) == 0);
        for (i = 0; i < n_ids; i++) {
            vec3 now = spin_of(w, id[i]);
            ENSURE_MSG(vec3_len(now) <= CAP * (1 + 1e-12), "ball %d spins at %.17g rad/s", i, vec3_len(now));
            ENSURE_MSG(vec3_len(vec3_sub(now, w0[i])) <= 1e-12 * CAP, "ball %d's spin moved by %.3g rad/s", i,
                       vec3_len(vec3_sub(now, w0[i])));
        }
        worst = fmax(worst, vrScene_Stats(w).energy - e0);
        ENSURE_MSG(vrScene_Stats(w).clamps == clamps, "frame %d: %lld clamps, %lld before it", f,
                   vrScene_Stats(w).clamps, clamps);
    }
    printf("    %d frames, %lld island steps: no cut, spin held; energy %.9g J -> %.9g J, above the start by %.3g J at most\n",
           frames, vrScene_Stats(w).island_steps, e0, vrScene_Stats(w).energy, worst);
    ENSURE(worst <= 1e-9 * e0);
    return 0;
}

/* A ball set spinning at 5.48 rad/s lies on a frictionless floor: placed,
 * its spin is cut to the cap (one clamp, spin energy 2/5 m r^2 4^2 / 2 =
 * 32 mJ), and that is all.  Each island step re-anchors it, and a spin of
 * 4 recomputed from L came out 4 + 1 ulp one step in five: 185 clamps in
 * 3 s, for the one cut. */
static int test_a_ball_spun_past_the_cap_on_a_frictionless_floor_is_cut_once(void)
{
    vrWorld *w = vrScene_World(0.01, 0.01, 9.8);
    double spin[3] = {-2, 5, 1};
    vrObjectId b;
    vrScene_Set(w, vrScene_ShellCaps);
    vrScene_Box(w, "floor", vec3_make(2, 2, 0.05), vec3_make(0, 0, -0.05), -1, 0.5);
    b = ball(w, "ball", 0, 0, vec3_zero());
    vrScene_Edit(w, b, vrScene_SetSpin, spin);
    ENSURE(vrScene_Step(w, 1) == 0);
    ENSURE(vrScene_Stats(w).clamps == 1);
    ENSURE_NEAR(vec3_len(spin_of(w, b)), CAP, 1e-12 * CAP);
    ENSURE_NEAR(vrScene_Stats(w).energy - 9.8 * vrScene_State(w, b).position[2], 0.5 * 0.4 * R * R * CAP * CAP, 1e-9);
    ENSURE(holds_its_spin(w, &b, 1, 300) == 0);
    vrWorld_Destroy(w);
    return 0;
}

/* Two rough balls (friction 0.5) on a frictionless floor: one slides at
 * 2 m/s, spinning at 2.4 rad/s, into the other 14 cm off its centre line,
 * and the friction of the impact spins them to 4.6 and 5.4 rad/s, over the
 * cap; each is cut once (a response that leaves a body over the cap is
 * one clamp, not two).  Then they slide apart spinning at the cap, and
 * nothing may cut them again: 314 clamps in 3 s counted the island steps'
 * rounding, and the one cut twice. */
static int test_balls_spun_past_the_cap_by_an_impact_are_cut_once_each(void)
{
    vrWorld *w = vrScene_World(0.01, 0.01, 9.8);
    double mu = 0.5, spin[3] = {1, 2, 1};
    vrObjectId id[2];
    int f;
    vrScene_Set(w, vrScene_ShellCaps);
    vrScene_Box(w, "floor", vec3_make(20, 20, 0.05), vec3_make(0, 0, -0.05), -1, 0.5);
    id[0] = ball(w, "a", -0.5, 0.14, vec3_make(2, 0, 0));
    id[1] = ball(w, "b", 0, 0, vec3_zero());
    vrScene_Edit(w, id[0], vrScene_SetSpin, spin);
    vrScene_Edit(w, id[0], set_friction, &mu);
    vrScene_Edit(w, id[1], set_friction, &mu);
    for (f = 0; f < 100 && vrScene_Stats(w).clamps == 0; f++) ENSURE(vrScene_Step(w, 1) == 0);
    printf("    impact in frame %d: %lld responses, %lld clamps; spins %.17g and %.17g rad/s\n", f,
           vrScene_Stats(w).collisions, vrScene_Stats(w).clamps, vec3_len(spin_of(w, id[0])),
           vec3_len(spin_of(w, id[1])));
    ENSURE(vrScene_Stats(w).clamps == 2);
    ENSURE_NEAR(vec3_len(spin_of(w, id[0])), CAP, 1e-12 * CAP);
    ENSURE_NEAR(vec3_len(spin_of(w, id[1])), CAP, 1e-12 * CAP);
    ENSURE(holds_its_spin(w, id, 2, 280) == 0);
    vrWorld_Destroy(w);
    return 0;
}

/* SPEC 3.2: a body the force speeds up to max_linear flies on at it (the
 * thesis's eq. 5), and that cut counts as an event's does: a ball dropped
 * 5 m onto a floor with e = 1 came back to 3.4 m with clamps = 0 and no
 * note.  A ball falling from rest reaches 8 m/s at 8 / 9.8 = 0.816 s, in
 * frame 17 of 0.05 s: one clamp then, and no more while it flies on at
 * the cap.  A second ball, dropped onto a floor so that it meets it at
 * 0.83 s, in the same frame, is counted once, when its anchor moves. */
static int test_a_ball_falling_to_the_cap_counts_one_clamp(void)
{
    vrWorld *w = vrScene_World(0.05, 0.01, 9.8);
    vrObjectId far, hit;
    vrScene_Set(w, vrScene_ShellCaps);
    far = vrScene_Sphere(w, "far", R, vec3_make(0, 0, 100), vec3_zero(), 1, 1);
    ENSURE(vrScene_Step(w, 16) == 0);
    ENSURE(vrScene_Stats(w).clamps == 0);
    ENSURE(vrScene_Step(w, 1) == 0);
    ENSURE(vrScene_Stats(w).clamps == 1);
    ENSURE(vrScene_Step(w, 20) == 0);
    ENSURE(vrScene_Stats(w).clamps == 1);
    ENSURE_NEAR(vrScene_State(w, far).linear_vel[2], -8, 1e-12);
    vrWorld_Destroy(w);
    w = vrScene_World(0.05, 0.01, 9.8);
    vrScene_Set(w, vrScene_ShellCaps);
    vrScene_Box(w, "floor", vec3_make(2, 2, 0.05), vec3_make(0, 0, -0.05), -1, 0.5);
    hit = vrScene_Sphere(w, "hit", R, vec3_make(0, 0, R + 0.5 * 9.8 * (8 / 9.8) * (8 / 9.8) + 8 * (0.83 - 8 / 9.8)),
                         vec3_zero(), 1, 0.5);
    ENSURE(vrScene_Step(w, 18) == 0);
    printf("    %lld responses, %lld clamps; vz %.9f m/s after the bounce\n", vrScene_Stats(w).collisions,
           vrScene_Stats(w).clamps, vrScene_State(w, hit).linear_vel[2]);
    ENSURE(vrScene_Stats(w).collisions == 1);
    ENSURE(vrScene_Stats(w).clamps == 1);
    ENSURE(vrScene_State(w, hit).linear_vel[2] > 3);
    vrWorld_Destroy(w);
    return 0;
}

static const vrTest tests[] = {
    TEST(test_a_ball_spun_past_the_cap_on_a_frictionless_floor_is_cut_once),
    TEST(test_balls_spun_past_the_cap_by_an_impact_are_cut_once_each),
    TEST(test_a_ball_falling_to_the_cap_counts_one_clamp),
};

const vrTestSuite vrSuite_Clamps = {"clamps", tests, TEST_COUNT(tests), NULL, NULL, 0};
