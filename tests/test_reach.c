/* test_reach.c — the grid's largest reach from the tree of bounds
 * (reach.c) is the same number as a look at every body (SPEC 3.2), through
 * a frame of events that re-anchor bodies: speeds near and at the cap,
 * spinning boxes, bodies sliding on supports (less acceleration than the
 * force), resting ones. */
#include <string.h>
#include "test.h"
#include "reach.h"
#include "schedule.h"

#define TEST_LCG_SEED 9191ULL
#include "test_lcg.h"

#define NB 300

static vrBody body[NB];
static vrBody *ptr[NB];

/* a new state for body i at t: a sphere or an isotropic box, sometimes
 * sliding on a level or tilted support (no or less acceleration), sometimes
 * resting, at 4 to 6.5 m/s (the cap is 6) in any direction, spinning at up
 * to 5 rad/s.  Speeds this close together change order within a frame as
 * gravity speeds some up and slows others down. */
static void anchor(int i, double t, const vrFlight *f)
{
    vrBody *b = &body[i];
    double r = 0.1 + 0.2 * uni();
    int sphere = uni() < 0.5;
    mat33 unit = mat33_diag(0.4 * r * r, 0.4 * r * r, 0.4 * r * r);
    vec3 spin = sphere ? vec3_zero() : rvec(5 / 1.8);
    vec3 v = vec3_scale(vec3_normalize(rvec(1)), 4 + 2.5 * uni());
    memset(b, 0, sizeof *b);
    b->id = i;
    b->shape.kind = sphere ? VR_SHAPE_SPHERE : VR_SHAPE_BOX;
    b->shape.radius = r;
    vrBody_SetMassProperties(b, 1, &unit, sphere ? r : 0.6 * r, r);
    b->contact = uni() < 0.3;      /* an island's contact step: no global force */
    b->resting = uni() < 0.1;
    vrBody_Anchor(b, t, rvec(5), v, quat_identity(), vec3_scale(spin, 0.4 * r * r), f);
    ptr[i] = b;
}

static double every_body(double ts, double T, const vrFlight *f)
{
    double best = 0;
    int i;
    for (i = 0; i < NB; i++) best = vr_max(best, vrSchedule_Reach(ptr[i], ts, T, f));
    return best;
}

static int test_tree_gives_the_reach_of_every_body(void)
{
    vrFlight f;
    vrReach r;
    int frame, k, i, pruned_bounds = 0;
    f.accel = vec3_make(0, 0, -9.8);
    f.max_linear = 6;
    f.max_angular = 100;
    vrReach_Init(&r);
    for (frame = 0; frame < 3; frame++) {
        double t0 = 0.1 * frame, T = t0 + 0.1;
        for (i = 0; i < NB; i++)
            if (frame == 0) anchor(i, 0, &f);
        vrReach_Frame(&r, ptr, NB, t0, T, &f);
        ENSURE(r.valid);
        for (k = 0; k < 400; k++) {
            double ts = t0 + 0.1 * (k + 1) / 401.0, exact;
            int changed = (int)(uni() * NB);
            anchor(changed, ts, &f);
            vrReach_Changed(&r, ptr, changed, ts, &f);
            exact = every_body(ts, T, &f);
            ENSURE_MSG(vrReach_Fastest(&r, ptr, ts, &f) == exact, "frame %d event %d: %.17g vs %.17g", frame, k,
                       vrReach_Fastest(&r, ptr, ts, &f), exact);
        }
        for (i = 0; i < NB; i++) pruned_bounds += r.bound[r.leaves + i] < r.bound[1];
    }
    /* the bounds are not all one number: the tree does prune */
    ENSURE(pruned_bounds > NB);
    vrReach_Free(&r);
    return 0;
}

static const vrTest tests[] = {
    TEST(test_tree_gives_the_reach_of_every_body),
};

const vrTestSuite vrSuite_Reach = {"reach", tests, TEST_COUNT(tests), NULL, NULL, 0};
