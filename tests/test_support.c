/* test_support.c — the face shortcut of the support-feature search.
 *
 * canonical.c takes the walk's face as a body's support feature at once when
 * the direction is so near its normal that the search could find nothing
 * else (face_is_support).  That rule is internal, so this file calls the
 * search (canonical.h) both ways on the same direction: from the face (the
 * shortcut may apply) and from one of its vertices (the search always runs).
 */
#include "canonical.h"
#include "primitives.h"
#include "test.h"

#define TEST_LCG_SEED 0x9E3779B97F4A7C15ULL
#include "test_lcg.h"

/* the same feature and the same vertices */
static int same_support(const vrSupportFeature *x, const vrSupportFeature *y)
{
    return x->kind == y->kind && x->index == y->index && x->v.n == y->v.n
        && memcmp(x->v.v, y->v.v, (size_t)x->v.n * sizeof x->v.v[0]) == 0;
}

/* Every face of a cube, a plate, a sphere mesh and two superquadrics, the
 * direction its normal tilted by 0 to 1e-6 rad about a random axis in its
 * plane (across the 1e-9 m tolerance): the support from the face equals the
 * support searched from its first vertex.  Counts how often the face was the
 * answer, so that both sides of the rule are seen. */
static int test_face_shortcut_equals_the_search(void)
{
    static const double tilt[] = {0, 1e-15, 1e-12, 1e-11, 1e-10, 3e-10, 1e-9, 3e-9, 1e-8, 1e-7, 1e-6};
    vrPolyhedron *p[5] = {NULL};
    char err[128];
    int s, f, k, faces = 0, others = 0, rc = 1;
    vrPose at0 = vrPose_make(vec3_zero(), quat_identity());
    if (vrPolyhedron_Cube(vec3_make(0.25, 0.25, 0.25), &p[0], err, sizeof err)
        || vrPolyhedron_Cube(vec3_make(2, 1, 0.05), &p[1], err, sizeof err)
        || vrPolyhedron_Sphere(0.3, 10, 10, &p[2], err, sizeof err)
        || vrPolyhedron_Superquadric(0.3, 0.3, vec3_make(0.3, 0.2, 0.25), 12, 12, &p[3], err, sizeof err)
        || vrPolyhedron_Superquadric(0.1, 0.1, vec3_make(1.5, 1, 0.5), 16, 16, &p[4], err, sizeof err))
        goto out;
    for (s = 0; s < 5; s++)
        for (f = 0; f < p[s]->nf; f++)
            for (k = 0; k < (int)(sizeof tilt / sizeof tilt[0]); k++) {
                vrPosed b;
                vrSupportFeature fast, search;
                vec3 n = p[s]->face_normal[f], t1 = vec3_orthogonal(n), t2 = vec3_cross(n, t1);
                double phi = 2 * VR_PI * uni();
                vec3 axis = vec3_add(vec3_scale(t1, cos(phi)), vec3_scale(t2, sin(phi)));
                vec3 dir = quat_rotate(quat_from_axis_angle(axis, tilt[k]), n);
                vrFeature face = {VR_FACE, f}, vertex = {VR_VERTEX, p[s]->face_vert[p[s]->face_start[f]]};
                b.p = p[s], b.pose = &at0;
                vrIntSet_Init(&fast.v);
                vrIntSet_Init(&search.v);
                ENSURE(vrSupportFeature_Find(&b, dir, face, &fast) == 0
                       && vrSupportFeature_Find(&b, dir, vertex, &search) == 0);
                ENSURE_MSG(same_support(&fast, &search), "shape %d face %d tilt %g: kind %d/%d index %d/%d, %d/%d vertices",
                           s, f, tilt[k], fast.kind, search.kind, fast.index, search.index, fast.v.n, search.v.n);
                if (fast.kind == VR_FACE && fast.index == f) faces++;
                else others++;
                vrIntSet_Free(&fast.v);
                vrIntSet_Free(&search.v);
            }
    printf("    the face itself %d times, another feature %d times\n", faces, others);
    ENSURE(faces > 0 && others > 0);
    rc = 0;
out:
    for (s = 0; s < 5; s++) vrPolyhedron_Free(p[s]);
    return rc;
}

static const vrTest tests[] = {
    TEST(test_face_shortcut_equals_the_search),
};

const vrTestSuite vrSuite_Support = {"support", tests, TEST_COUNT(tests), NULL, NULL, 0};
