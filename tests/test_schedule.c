/* test_schedule.c — the expected earliest event time (SPEC 3.3) is a true
 * lower bound: sampled along the real motion, no pair comes within d before
 * its key; and the internal-step grid keeps every step under d/2 of travel. */
#include <string.h>
#include "test.h"
#include "schedule.h"

#define TEST_LCG_SEED 777ULL
#include "test_lcg.h"

static vrPolyhedron *cube_poly;

static void make_body(vrBody *b, int id, int sphere, int is_static)
{
    double h = 0.1 + 0.3 * uni();
    mat33 unit;
    memset(b, 0, sizeof *b);
    b->id = id;
    if (sphere) {
        b->shape.kind = VR_SHAPE_SPHERE;
        b->shape.radius = h;
        unit = mat33_diag(0.4 * h * h, 0.4 * h * h, 0.4 * h * h);
        vrBody_SetMassProperties(b, is_static ? -1 : 1, &unit, h, h);
    } else {
        b->shape.kind = VR_SHAPE_BOX;
        b->shape.half = vec3_make(0.2, 0.2, 0.2);
        b->shape.poly = cube_poly;
        vrBody_SetMassProperties(b, is_static ? -1 : 1, &cube_poly->inertia_unit, cube_poly->r_in, cube_poly->r_out);
    }
}

static double distance(vrBody *a, vrBody *b, double t, vrWalkCache *c, vec3 *n)
{
    vrPose pa, pb;
    vrContact ct;
    vrBody_Pose(a, t, &pa);
    vrBody_Pose(b, t, &pb);
    vrContact_Distance(&a->shape, &pa, &b->shape, &pb, c, &ct);
    if (n) *n = ct.n;
    return ct.dist;
}

static int test_key_never_overestimates(void)
{
    vrFlight f;
    int trial, violations = 0, finite = 0;
    f.max_linear = 6;
    f.max_angular = 5;
    ENSURE(vrPolyhedron_Cube(vec3_make(0.2, 0.2, 0.2), &cube_poly, NULL, 0) == 0);
    for (trial = 0; trial < 3000; trial++) {
        vrBody a, b;
        vrWalkCache cache;
        double d = 0.01 + 0.1 * uni(), key, D0;
        vec3 n0;
        int k;
        memset(&cache, 0, sizeof cache);
        f.accel = trial % 3 ? vec3_make(0, 0, -9.8) : vec3_zero();
        make_body(&a, 1, trial % 2, 0);
        make_body(&b, 2, trial % 5 < 2, trial % 4 == 0);
        if (trial % 7 == 0) b.nsupport = 1, b.support[0].partner = 9, b.support[0].n = vec3_make(0, 0, 1);
        vrBody_Anchor(&a, 0, vec3_zero(), rvec(5), quat_normalize(quat_make(sym(1), sym(1), sym(1), sym(1))),
                      vec3_scale(rvec(1), 0.1), &f);
        vrBody_Anchor(&b, 0, vec3_add(vec3_make(1.5, 0, 0), rvec(1)), rvec(5),
                      quat_normalize(quat_make(sym(1), sym(1), sym(1), sym(1))), vec3_scale(rvec(1), 0.1), &f);
        D0 = distance(&a, &b, 0, &cache, &n0);
        if (D0 <= d) continue;
        key = vrSchedule_Key(&a, &b, 0, D0, n0, d, &f);
        if (key < INFINITY) finite++;
        for (k = 1; k <= 200; k++) {
            double t = fmin(key, 3.0) * k / 200.0;
            if (t >= key) break;
            if (distance(&a, &b, t, &cache, NULL) <= d) { violations++; break; }
        }
    }
    vrPolyhedron_Free(cube_poly);
    printf("    %d finite keys, %d violations\n", finite, violations);
    ENSURE(finite > 1000);
    ENSURE(violations == 0);
    return 0;
}

/* SPEC 3.2: the grid for free bodies is n = ceil(span * 2 * reach / d) */
static int test_grid_follows_thesis_rule_without_spin(void)
{
    vrBody b, *list[1] = {&b};
    vrFlight f;
    vrGrid g;
    mat33 unit = mat33_diag(0.004, 0.004, 0.004);
    memset(&b, 0, sizeof b);
    b.shape.kind = VR_SHAPE_SPHERE;
    b.shape.radius = 0.1;
    vrBody_SetMassProperties(&b, 1, &unit, 0.1, 0.1);
    f.accel = vec3_zero();
    f.max_linear = 8;
    f.max_angular = 4;
    vrBody_Anchor(&b, 0, vec3_zero(), vec3_make(8, 0, 0), quat_identity(), vec3_zero(), &f);
    vrSchedule_Grid(list, 1, 0, 0.1, 0.25, 0, &f, &g);
    ENSURE(g.n == 7);                         /* ceil(0.1 * 2 * 8 / 0.25) = ceil(6.4) */
    ENSURE(vrGrid_Point(&g, g.n) == 0.1);
    vrSchedule_Grid(list, 1, 0.1, 0.1, 0.25, 0, &f, &g);
    ENSURE(g.n == 0);                         /* nothing left of the frame */
    b.resting = 1;
    vrSchedule_Grid(list, 1, 0, 0.1, 0.25, 0, &f, &g);
    ENSURE(g.n == 1);                         /* nothing free: one step */
    return 0;
}

int main(int argc, char **argv)
{
    test_init(argc, argv);
    RUN_TEST(test_key_never_overestimates);
    RUN_TEST(test_grid_follows_thesis_rule_without_spin);
    return test_summary();
}
