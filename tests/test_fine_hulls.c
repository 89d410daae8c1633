/* test_fine_hulls.c — a fine hull (a superquadric of thousands of points)
 * answered by shortcuts that must give the exhaustive answers: the support
 * vertex by a climb instead of a scan of every vertex (shape.c), the
 * farthest-apart face by groups of faces bounded together instead of every
 * face (face_groups.c, contact.c's touching_axis), and the vertices above a
 * plane met through a hash instead of a scan (vertex_set.c).  Each is
 * checked against the plain method, to the bit. */
#include <stdlib.h>
#include <string.h>
#include "closest.h"
#include "contact.h"
#include "face_groups.h"
#include "primitives.h"
#include "shape.h"
#include "vertex_set.h"
#include "test.h"

#define TEST_LCG_SEED 0x2545F4914F6CDD1DULL
#include "test_lcg.h"

/* a smooth one, a near box (big flat faces: ties along the axes), a pinched one */
static int fine_hulls(vrPolyhedron *p[3])
{
    char err[256];
    memset(p, 0, 3 * sizeof *p);
    if (vrPolyhedron_Superquadric(1, 1, vec3_make(0.4, 0.3, 0.35), 40, 40, &p[0], err, sizeof err)
        || vrPolyhedron_Superquadric(0.1, 0.1, vec3_make(0.5, 0.3, 0.2), 40, 40, &p[1], err, sizeof err)
        || vrPolyhedron_Superquadric(0.6, 1.6, vec3_make(0.3, 0.4, 0.3), 50, 50, &p[2], err, sizeof err)) {
        printf("    %s\n", err);
        return -1;
    }
    return 0;
}

static void free_hulls(vrPolyhedron *p[3])
{
    int i;
    for (i = 0; i < 3; i++) vrPolyhedron_Free(p[i]);
}

static int same(vec3 a, vec3 b) { return a.x == b.x && a.y == b.y && a.z == b.z; }

static vrPose random_pose(vec3 at)
{
    return vrPose_make(at, quat_normalize(quat_make(sym(1), sym(1), sym(1), sym(1))));
}

/* the scan's answer: the highest along dir, the first of equals */
static vec3 scanned_support(const vrPolyhedron *p, const vrPose *pose, vec3 dir)
{
    vec3 d = mat33_tmulv(&pose->R, dir);
    int i, best = 0;
    for (i = 1; i < p->nv; i++)
        if (vec3_dot(d, p->vert[i]) > vec3_dot(d, p->vert[best])) best = i;
    return vrPose_apply(pose, p->vert[best]);
}

/* Random directions, the body axes (where a flat face ties its vertices)
 * and directions a hair off them, from random start vertices and from
 * where the last climb ended: the climb's vertex is the scan's, to the bit. */
static int test_a_climbed_support_is_the_scanned_one(void)
{
    vrPolyhedron *p[3];
    int s, i, checked = 0;
    ENSURE(fine_hulls(p) == 0);
    for (s = 0; s < 3; s++) {
        vrShape sh;
        vrPose pose = random_pose(rvec(2));
        int hint = -1;
        memset(&sh, 0, sizeof sh);
        sh.kind = VR_SHAPE_POLY, sh.poly = p[s];
        ENSURE(p[s]->nv > 64);   /* climbed, not scanned */
        for (i = 0; i < 3000; i++) {
            vec3 dir = rvec(1), got, want;
            if (i % 3 == 1) dir = mat33_col(&pose.R, i % 9 / 3);   /* a body axis */
            if (i % 3 == 2) dir = vec3_add(mat33_col(&pose.R, i % 9 / 3), rvec(1e-12));
            if (i % 7 == 0) hint = (int)(uni() * p[s]->nv);
            got = vrShape_SupportFrom(&sh, &pose, dir, &hint);
            want = scanned_support(p[s], &pose, dir);
            ENSURE_MSG(got.x == want.x && got.y == want.y && got.z == want.z, "hull %d, direction %d", s, i);
            checked++;
        }
    }
    printf("    %d directions on hulls of %d, %d and %d vertices\n", checked, p[0]->nv, p[1]->nv, p[2]->nv);
    free_hulls(p);
    return 0;
}

/* Every face in one group, ascending within it, and each group's bound
 * above n.o - offset of each of its faces for points near and far */
static int test_face_group_bounds_hold(void)
{
    vrPolyhedron *p[3];
    int s, i, f, k, faces = 0;
    ENSURE(fine_hulls(p) == 0);
    for (s = 0; s < 3; s++) {
        const vrFaceGroups *gs = p[s]->groups;
        int *seen = calloc((size_t)p[s]->nf, sizeof *seen);
        ENSURE(gs != NULL && seen != NULL);
        for (k = 0; k < gs->n; k++)
            for (i = 0; i < gs->group[k].n; i++) {
                f = gs->face[gs->group[k].start + i];
                ENSURE(f >= 0 && f < p[s]->nf && !seen[f]);
                seen[f] = 1;
                if (i > 0) ENSURE(f > gs->face[gs->group[k].start + i - 1]);
            }
        for (f = 0; f < p[s]->nf; f++) ENSURE(seen[f]);
        free(seen);
        for (i = 0; i < 200; i++) {
            vec3 o = rvec(i % 2 ? 0.6 : 3);
            for (k = 0; k < gs->n; k++) {
                const vrFaceGroup *g = &gs->group[k];
                double bound = vrFaceGroup_Bound(g, o);
                for (f = 0; f < g->n; f++) {
                    int x = gs->face[g->start + f];
                    ENSURE(bound >= vec3_dot(p[s]->face_normal[x], o) - p[s]->face_offset[x]);
                }
            }
        }
        faces += p[s]->nf;
    }
    printf("    %d faces in %d, %d and %d groups\n", faces, p[0]->groups->n, p[1]->groups->n, p[2]->groups->n);
    free_hulls(p);
    return 0;
}

/* Two fine hulls touching (0.1 um apart to 10 um into each other, where
 * the contact takes the face along which they lie farthest apart) in
 * random poses: the contact with the faces grouped is the one with every
 * face looked at (the same hulls with their groups taken away), to the
 * bit: distance, normal, closest points and region. */
static int test_a_touch_of_grouped_hulls_is_the_touch_of_every_face(void)
{
    vrPolyhedron *p[3], *q[3];
    int s, i, regions = 0;
    ENSURE(fine_hulls(p) == 0 && fine_hulls(q) == 0);
    for (s = 0; s < 3; s++) {
        vrFaceGroups_Free(q[s]->groups);
        q[s]->groups = NULL;
    }
    for (i = 0; i < 300; i++) {
        int a = i % 3, b = (i / 3) % 3;
        vrShape ga, gb, fa, fb;
        vrPose pa = random_pose(vec3_zero()), pb;
        vrContact c, grouped, every;
        vec3 dir = vec3_normalize(rvec(1));
        memset(&ga, 0, sizeof ga);
        ga.kind = gb.kind = fa.kind = fb.kind = VR_SHAPE_POLY;
        gb = fa = fb = ga;
        ga.poly = p[a], gb.poly = p[b], fa.poly = q[a], fb.poly = q[b];
        pb = random_pose(vec3_scale(dir, 1.5));
        ENSURE(vrContact_Distance(&ga, &pa, &gb, &pb, NULL, &c) == 0 && c.dist > 0);
        pb = vrPose_make(vec3_madd(pb.p, -c.dist + (i % 4 == 0 ? 1e-7 : -1e-5 * uni()), c.n), pb.q);
        ENSURE(vrContact_Region(&ga, &pa, &gb, &pb, 0.01, NULL, &grouped) == 0);
        ENSURE(vrContact_Region(&fa, &pa, &fb, &pb, 0.01, NULL, &every) == 0);
        ENSURE_MSG(grouped.dist == every.dist && same(grouped.n, every.n) && same(grouped.pa, every.pa)
                       && same(grouped.pb, every.pb) && grouped.npoints == every.npoints,
                   "pose %d: dist %.17g against %.17g", i, grouped.dist, every.dist);
        ENSURE(memcmp(grouped.point, every.point, (size_t)every.npoints * sizeof every.point[0]) == 0);
        regions += every.npoints > 1;
    }
    printf("    300 touches, %d with regions of several points\n", regions);
    ENSURE(regions > 0);
    free_hulls(p);
    free_hulls(q);
    return 0;
}

static int cmp_int(const void *x, const void *y) { return *(const int *)x - *(const int *)y; }

/* The vertices above a plane, collected from the top vertex over edges (a
 * hash says which were met once there are more than 32): the same set as
 * every vertex tested, for slabs of one to hundreds of vertices */
static int test_the_vertices_above_a_plane_are_all_met_once(void)
{
    vrPolyhedron *p[3];
    int s, i, v, big = 0;
    ENSURE(fine_hulls(p) == 0);
    for (s = 0; s < 3; s++)
        for (i = 0; i < 300; i++) {
            vec3 d = vec3_normalize(rvec(1));
            vrIntSet set;
            int top = 0, n = 0, *want = malloc((size_t)p[s]->nv * sizeof *want);
            double floor;
            ENSURE(want != NULL);
            for (v = 1; v < p[s]->nv; v++)
                if (vec3_dot(d, p[s]->vert[v]) > vec3_dot(d, p[s]->vert[top])) top = v;
            floor = vec3_dot(d, p[s]->vert[top]) - (i % 3 == 0 ? 1e-9 : 0.1 * uni());
            for (v = 0; v < p[s]->nv; v++)
                if (vec3_dot(d, p[s]->vert[v]) >= floor) want[n++] = v;
            vrIntSet_Init(&set);
            ENSURE(vrIntSet_Collect(p[s], d, top, floor, &set) == 0);
            ENSURE_MSG(set.n == n, "hull %d, plane %d: %d vertices met, %d above", s, i, set.n, n);
            qsort(set.v, (size_t)set.n, sizeof *set.v, cmp_int);
            ENSURE(memcmp(set.v, want, (size_t)n * sizeof *want) == 0);
            big += n > 32;
            vrIntSet_Free(&set);
            free(want);
        }
    printf("    900 planes, %d with more than 32 vertices above\n", big);
    ENSURE(big > 100);
    free_hulls(p);
    return 0;
}

/* b's centre placed so that its lowest vertex along u lies delta beyond
 * a's highest, along u: their distance delta when delta >= 0 (touches to
 * 1e-12 m), an overlap of about -delta when below */
static vec3 beyond_along(const vrPolyhedron *a, const vrPose *pa, const vrPolyhedron *b, const vrPose *pb, vec3 u,
                         double delta)
{
    vec3 top = vrPose_apply(pa, a->vert[0]), bottom = vrPose_apply(pb, b->vert[0]);
    int v;
    for (v = 1; v < a->nv; v++)
        if (vec3_dot(u, vrPose_apply(pa, a->vert[v])) > vec3_dot(u, top)) top = vrPose_apply(pa, a->vert[v]);
    for (v = 1; v < b->nv; v++)
        if (vec3_dot(u, vrPose_apply(pb, b->vert[v])) < vec3_dot(u, bottom)) bottom = vrPose_apply(pb, b->vert[v]);
    return vec3_add(pb->p, vec3_sub(vec3_madd(top, delta, u), bottom));
}

static vrFeature any_feature(const vrPolyhedron *p)
{
    int type = (int)(uni() * 3);
    return vrFeature_Make(type, (int)(uni() * (type == VR_VERTEX ? p->nv : type == VR_EDGE ? p->ne : p->nf)));
}

/* The exhaustive search the walk falls back on looks only at the
 * features in a slab between the bodies (closest_exhaustive.c; over every
 * pair, two touching 150 x 150 superquadrics took tens of seconds a
 * search).  Hulls coarse and finer (up to 900 points), vertex to vertex along a random
 * direction from 1 mm into each other to 5 cm apart (touches to 1e-12 m
 * among them), the search starting from random features: the same distance, points,
 * overlap flag and features as the search over every pair, to the bit. */
static int test_the_exhaustive_search_in_the_slab_is_the_search_over_every_pair(void)
{
    static const double delta[] = {-1e-3, -1e-9, -1e-12, 0, 1e-12, 1e-9, 1e-6, 1e-3, 0.05};
    vrPolyhedron *fine[3], *coarse[3];
    char err[256];
    int s, i, k, pen_seen = 0, apart_seen = 0, n = 0;
    memset(fine, 0, sizeof fine);
    memset(coarse, 0, sizeof coarse);
    ENSURE(vrPolyhedron_Superquadric(1, 1, vec3_make(0.4, 0.3, 0.35), 24, 24, &fine[0], err, sizeof err) == 0);
    ENSURE(vrPolyhedron_Superquadric(0.1, 0.1, vec3_make(0.5, 0.3, 0.2), 24, 24, &fine[1], err, sizeof err) == 0);
    ENSURE(vrPolyhedron_Superquadric(0.6, 1.6, vec3_make(0.3, 0.4, 0.3), 30, 30, &fine[2], err, sizeof err) == 0);
    ENSURE(vrPolyhedron_Superquadric(1, 1, vec3_make(0.4, 0.3, 0.35), 10, 10, &coarse[0], err, sizeof err) == 0);
    ENSURE(vrPolyhedron_Superquadric(0.1, 0.1, vec3_make(0.5, 0.3, 0.2), 12, 12, &coarse[1], err, sizeof err) == 0);
    ENSURE(vrPolyhedron_Cube(vec3_make(0.3, 0.2, 0.1), &coarse[2], err, sizeof err) == 0);
    for (s = 0; s < 3; s++)
        for (i = 0; i < 9 * (s == 0 ? 20 : 1); i++) {
            /* s = 0: coarse against coarse; 1: fine against coarse; 2: fine against fine */
            const vrPolyhedron *a = s == 0 ? coarse[i % 3] : fine[i % 3], *b = s < 2 ? coarse[(i / 3) % 3] : fine[(i + 1) % 3];
            vrPose pa = random_pose(rvec(1)), pb = random_pose(vec3_zero());
            vec3 u = vec3_normalize(rvec(1)), ca[2], cb[2];
            vrWalkCache c[2];
            double d[2];
            int pen[2];
            pb.p = beyond_along(a, &pa, b, &pb, u, delta[i % 9]);
            memset(c, 0, sizeof c);
            c[0].a = any_feature(a), c[0].b = any_feature(b), c[0].valid = 1;
            c[1] = c[0];
            d[0] = vrClosest_Exhaustive(a, &pa, b, &pb, &c[0], &ca[0], &cb[0], &pen[0]);
            d[1] = vrClosest_ExhaustiveAll(a, &pa, b, &pb, &c[1], &ca[1], &cb[1], &pen[1]);
            ENSURE_MSG(d[0] == d[1] && pen[0] == pen[1] && same(ca[0], ca[1]) && same(cb[0], cb[1]),
                       "case %d,%d (delta %g): %.17g against %.17g, overlap %d against %d", s, i, delta[i % 9], d[0],
                       d[1], pen[0], pen[1]);
            ENSURE_MSG(c[0].a.type == c[1].a.type && c[0].a.index == c[1].a.index && c[0].b.type == c[1].b.type
                           && c[0].b.index == c[1].b.index,
                       "case %d,%d: other features", s, i);
            pen_seen += pen[0], apart_seen += !pen[0] && d[0] < 1e-6;
            n++;
        }
    for (k = 0; k < 3; k++) vrPolyhedron_Free(coarse[k]);
    free_hulls(fine);
    printf("    %d searches: %d overlapping, %d apart by under 1e-6 m\n", n, pen_seen, apart_seen);
    ENSURE(pen_seen > 20 && apart_seen > 20);
    return 0;
}

static const vrTest tests[] = {
    TEST(test_a_climbed_support_is_the_scanned_one),
    TEST(test_face_group_bounds_hold),
    TEST(test_a_touch_of_grouped_hulls_is_the_touch_of_every_face),
    TEST(test_the_vertices_above_a_plane_are_all_met_once),
    TEST(test_the_exhaustive_search_in_the_slab_is_the_search_over_every_pair),
};

const vrTestSuite vrSuite_FineHulls = {"fine_hulls", tests, TEST_COUNT(tests), NULL, NULL, 0};
