/* test_closest.c — the closest-feature walk (closest.c) against brute force,
 * from every kind of start, on degenerate and coherent motion. */
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "contact.h"
#include "brute_distance.h"
#include "hull.h"
#include "off.h"
#include "penetration.h"
#include "primitives.h"
#include "test.h"

/* ---- fixtures --------------------------------------------------------- */

static unsigned long long rng_state = 0x9E3779B97F4A7C15ull;

static double urand(void) /* splitmix64, [0, 1) */
{
    unsigned long long z = (rng_state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return (double)((z ^ (z >> 31)) >> 11) / 9007199254740992.0;
}
static double urange(double lo, double hi) { return lo + (hi - lo) * urand(); }
static vec3 udir(void) /* uniform on the sphere */
{
    double z = urange(-1, 1), a = urange(0, 2 * VR_PI), s = sqrt(1 - z * z);
    return vec3_make(s * cos(a), s * sin(a), z);
}
static quat uquat(void) { return quat_from_axis_angle(udir(), urange(0, VR_PI)); }

enum { S_CUBE, S_PLATE, S_MESH, S_SQ03, S_SQ1, S_SQ2, S_HULL, S_OFF, NSHAPES };
static const char *shape_name[NSHAPES] = {"cube", "box", "mesh10", "sq0.3", "sq1", "sq2", "hull", "off"};
static vrPolyhedron *shape[NSHAPES];

/* an octahedron with one apex pulled out, as an OFF file */
static int write_off(char *path)
{
    static const char text[] = "OFF\n6 8 12\n1 0 0\n-1 0 0\n0 1 0\n0 -1 0\n0 0 1.5\n0 0 -1\n"
                               "3 0 2 4\n3 2 1 4\n3 1 3 4\n3 3 0 4\n3 2 0 5\n3 1 2 5\n3 3 1 5\n3 0 3 5\n";
    int fd = mkstemp(path);
    if (fd < 0) return -1;
    if (write(fd, text, sizeof text - 1) != (ssize_t)(sizeof text - 1)) {
        close(fd);
        return -1;
    }
    return close(fd);
}

static int make_shapes(void)
{
    char err[256], path[] = "/tmp/vroc_test_closest_XXXXXX";
    vec3 pts[40];
    int i, rc = 0;
    if (shape[0]) return 0;
    for (i = 0; i < 40; i++) pts[i] = vec3_scale(udir(), urange(0.2, 0.45));
    rc |= vrPolyhedron_Cube(vec3_make(0.25, 0.25, 0.25), &shape[S_CUBE], err, sizeof err);
    rc |= vrPolyhedron_Cube(vec3_make(0.4, 0.15, 0.05), &shape[S_PLATE], err, sizeof err);
    rc |= vrPolyhedron_Sphere(0.3, 10, 10, &shape[S_MESH], err, sizeof err);
    rc |= vrPolyhedron_Superquadric(0.3, 0.3, vec3_make(0.3, 0.25, 0.2), 12, 12, &shape[S_SQ03], err, sizeof err);
    rc |= vrPolyhedron_Superquadric(1, 1, vec3_make(0.3, 0.2, 0.25), 12, 12, &shape[S_SQ1], err, sizeof err);
    rc |= vrPolyhedron_Superquadric(2, 2, vec3_make(0.3, 0.3, 0.3), 12, 12, &shape[S_SQ2], err, sizeof err);
    rc |= vrPolyhedron_Hull(pts, 40, &shape[S_HULL], err, sizeof err);
    if (rc == 0 && write_off(path) == 0) {
        rc |= vrPolyhedron_FromOFF(path, &shape[S_OFF], err, sizeof err);
        unlink(path);
    }
    if (rc) printf("    shape builder failed: %s\n", err);
    return rc || !shape[S_OFF];
}

static vrPose pose(vec3 p, quat q) { return vrPose_make(p, q); }

/* b placed around a at a random direction and centre distance */
static void random_pair(const vrPolyhedron *a, const vrPolyhedron *b, double lo, double hi, vrPose *pa, vrPose *pb)
{
    double r = (a->r_out + b->r_out) * urange(lo, hi);
    vec3 c = vec3_make(urange(-1, 1), urange(-1, 1), urange(-1, 1));
    *pa = pose(c, uquat());
    *pb = pose(vec3_madd(c, r, udir()), uquat());
}

static vrFeature random_feature(const vrPolyhedron *p)
{
    vrFeature f;
    f.type = (int)(urand() * 3);
    f.index = (int)(urand() * (f.type == VR_VERTEX ? p->nv : f.type == VR_EDGE ? p->ne : p->nf));
    return f;
}

static vrWalkCache random_cache(const vrPolyhedron *a, const vrPolyhedron *b)
{
    vrWalkCache c;
    memset(&c, 0, sizeof c);
    c.a = random_feature(a);
    c.b = random_feature(b);
    c.valid = 1;
    return c;
}

/* largest height of x above p's face planes: ~0 for a point on the surface */
static double surface_height(const vrPolyhedron *p, const vrPose *ps, vec3 x)
{
    vec3 xb = vrPose_invapply(ps, x);
    double m = -HUGE_VAL;
    int f;
    for (f = 0; f < p->nf; f++) {
        double h = vec3_dot(p->face_normal[f], xb) - p->face_offset[f];
        if (h > m) m = h;
    }
    return m;
}

/* libccd's depth when the polyhedra overlap, else 0 */
static double overlap_depth(const vrPolyhedron *a, const vrPose *pa, const vrPolyhedron *b, const vrPose *pb)
{
    vrShape sa = {VR_SHAPE_POLY, 0, {0, 0, 0}, NULL, 0}, sb = sa;
    vec3 dir, pos;
    double depth;
    sa.poly = a;
    sb.poly = b;
    return vrPenetration(&sa, pa, &sb, pb, &depth, &dir, &pos) == 0 ? depth : 0;
}

/* one walk query checked against brute force: distance, and closest points on
 * the surfaces at that distance */
static int check_walk(const vrPolyhedron *a, const vrPose *pa, const vrPolyhedron *b, const vrPose *pb,
                      vrWalkCache *cache, double bf, int *steps)
{
    vec3 ca, cb;
    int pen;
    double d = vrClosest_Walk(a, pa, b, pb, cache, &ca, &cb, steps, &pen);
    double tol = 1e-9 * (d > 1 ? d : 1);
    ENSURE_MSG(!pen, "walk says penetrating, brute force %.17g", bf);
    ENSURE_NEAR(d, bf, tol);
    ENSURE_NEAR(vec3_dist(ca, cb), d, tol);
    ENSURE_NEAR(surface_height(a, pa, ca), 0, 1e-9);
    ENSURE_NEAR(surface_height(b, pb, cb), 0, 1e-9);
    return 0;
}

/* ---- tests ------------------------------------------------------------ */

/* 10,000+ separated random pose pairs over every pair of shapes, each from
 * the previous query's cache, a random cache and the empty cache. */
static int test_walk_matches_brute_force_on_random_poses(void)
{
    int i, j, k, n = 0, steps;
    ENSURE(make_shapes() == 0);
    for (i = 0; i < NSHAPES; i++)
        for (j = i; j < NSHAPES; j++) {
            vrWalkCache warm;
            memset(&warm, 0, sizeof warm);
            for (k = 0; k < 480; k++) {
                vrPose pa, pb;
                vrWalkCache rnd = random_cache(shape[i], shape[j]), zero;
                double bf;
                memset(&zero, 0, sizeof zero);
                random_pair(shape[i], shape[j], 0.4, 1.3, &pa, &pb);
                if (overlap_depth(shape[i], &pa, shape[j], &pb) > 1e-6) continue; /* saves brute force time */
                bf = vrClosest_BruteForce(shape[i], &pa, shape[j], &pb);
                if (bf <= 1e-6) continue;
                n++;
                if (check_walk(shape[i], &pa, shape[j], &pb, &warm, bf, &steps)
                    || check_walk(shape[i], &pa, shape[j], &pb, &rnd, bf, &steps)
                    || check_walk(shape[i], &pa, shape[j], &pb, &zero, bf, &steps)) {
                    printf("    %s-%s, pose %d\n", shape_name[i], shape_name[j], k);
                    return 1;
                }
                ENSURE(warm.fallbacks + rnd.fallbacks + zero.fallbacks == 0);
            }
        }
    printf("    %d separated pose pairs, 3 starts each\n", n);
    ENSURE(n >= 10000);
    return 0;
}

/* A smooth motion (0.3 degree and 1 mm per query) of two 10x10 sphere meshes
 * costs well under one feature step per query: the thesis's "approximately
 * constant time" (3.2.1). */
static int test_walk_is_coherent_along_smooth_motion(void)
{
    vrWalkCache cache;
    vec3 w = vec3_normalize(vec3_make(0.3, -1, 0.5)), v = vec3_make(0.0007, 0.0003, -0.0002);
    vrPose pa = pose(vec3_zero(), quat_identity()), pb;
    quat q = quat_identity();
    vec3 p = vec3_make(0.7, 0.1, 0.05);
    long total = 0;
    int k, n = 20000, steps;
    ENSURE(make_shapes() == 0);
    memset(&cache, 0, sizeof cache);
    for (k = 0; k < n; k++) {
        double bf;
        q = quat_normalize(quat_mul(quat_from_rotvec(vec3_scale(w, 0.005)), q));
        p = vec3_add(p, v);
        if (vec3_len(p) > 0.9 || vec3_len(p) < 0.65) v = vec3_neg(v);
        pb = pose(p, q);
        if (k % 97 == 0) { /* spot checks */
            bf = vrClosest_BruteForce(shape[S_MESH], &pa, shape[S_MESH], &pb);
            if (check_walk(shape[S_MESH], &pa, shape[S_MESH], &pb, &cache, bf, &steps)) return 1;
        } else {
            vec3 ca, cb;
            int pen;
            vrClosest_Walk(shape[S_MESH], &pa, shape[S_MESH], &pb, &cache, &ca, &cb, &steps, &pen);
            ENSURE(!pen);
        }
        total += steps;
    }
    printf("    mean feature steps per query: %.3f\n", (double)total / n);
    ENSURE((double)total / n < 0.5);
    ENSURE(cache.fallbacks == 0);
    return 0;
}

/* every start pair of features of a and b: the walk ends without the
 * exhaustive fallback, at the expected distance */
static int walk_from_every_start(const vrPolyhedron *a, const vrPose *pa, const vrPolyhedron *b, const vrPose *pb,
                                 double expect)
{
    int ta, ia, tb, ib, na[3] = {a->nv, a->ne, a->nf}, nb[3] = {b->nv, b->ne, b->nf};
    for (ta = 0; ta < 3; ta++)
        for (ia = 0; ia < na[ta]; ia++)
            for (tb = 0; tb < 3; tb++)
                for (ib = 0; ib < nb[tb]; ib++) {
                    vrWalkCache c;
                    vec3 ca, cb;
                    int steps, pen;
                    double d;
                    memset(&c, 0, sizeof c);
                    c.a.type = ta, c.a.index = ia, c.b.type = tb, c.b.index = ib, c.valid = 1;
                    d = vrClosest_Walk(a, pa, b, pb, &c, &ca, &cb, &steps, &pen);
                    ENSURE_MSG(c.fallbacks == 0 && !pen, "start %d/%d %d/%d: fallback %u pen %d", ta, ia, tb, ib,
                               c.fallbacks, pen);
                    ENSURE_NEAR(d, expect, 1e-12);
                }
    return 0;
}

/* Parallel faces, parallel edges, vertex over vertex, symmetric stacks. */
static int test_walk_terminates_on_degenerate_configurations(void)
{
    vrPolyhedron *table, *cube;
    char err[128];
    quat q45x = quat_from_axis_angle(vec3_make(1, 0, 0), VR_PI / 4);
    quat q45z = quat_from_axis_angle(vec3_make(0, 0, 1), VR_PI / 4);
    quat corner = quat_from_axis_angle(vec3_normalize(vec3_make(1, -1, 0)), acos(1 / sqrt(3.0)));
    vrPose at0 = pose(vec3_zero(), quat_identity()), pb;
    double r2 = 0.25 * sqrt(2.0), r3 = 0.25 * sqrt(3.0);
    ENSURE(make_shapes() == 0);
    ENSURE(vrPolyhedron_Cube(vec3_make(1, 0.5, 0.025), &table, err, sizeof err) == 0);
    cube = shape[S_CUBE];
    /* box flat on a table, edges parallel, off centre and overhanging */
    pb = pose(vec3_make(0.3, 0.1, 0.025 + 0.25 + 0.01), quat_identity());
    if (walk_from_every_start(table, &at0, cube, &pb, 0.01)) goto fail;
    pb = pose(vec3_make(0.9, 0.4, 0.025 + 0.25 + 0.01), q45z);
    if (walk_from_every_start(table, &at0, cube, &pb, 0.01)) goto fail;
    /* equal cubes stacked exactly: faces, edges and vertices all coincide in projection */
    pb = pose(vec3_make(0, 0, 0.5 + 0.02), quat_identity());
    if (walk_from_every_start(cube, &at0, cube, &pb, 0.02)) goto fail;
    /* parallel edges: both cubes on an edge, one above the other */
    pb = pose(vec3_make(0.1, 0, 2 * r2 + 0.03), q45x);
    {
        vrPose pa = pose(vec3_zero(), q45x);
        if (walk_from_every_start(cube, &pa, cube, &pb, 0.03)) goto fail;
    }
    /* crossed edges, symmetric about the axis */
    {
        vrPose pa = pose(vec3_zero(), q45x);
        pb = pose(vec3_make(0, 0, 2 * r2 + 0.03), quat_mul(q45z, quat_mul(q45z, q45x)));
        if (walk_from_every_start(cube, &pa, cube, &pb, 0.03)) goto fail;
    }
    /* vertex over vertex: a cube on its corner over another's corner */
    {
        vrPose pa = pose(vec3_zero(), quat_conj(corner));
        pb = pose(vec3_make(0, 0, 2 * r3 + 0.01), corner);
        if (walk_from_every_start(cube, &pa, cube, &pb, 0.01)) goto fail;
    }
    /* sphere meshes pole to pole, and a pole over the middle of the table */
    pb = pose(vec3_make(0, 0, 0.6 + 0.005), quat_identity());
    if (walk_from_every_start(shape[S_MESH], &at0, shape[S_MESH], &pb, 0.005)) goto fail;
    pb = pose(vec3_make(0, 0, 0.025 + 0.3 + 0.005), quat_identity());
    if (walk_from_every_start(table, &at0, shape[S_MESH], &pb, 0.005)) goto fail;
    vrPolyhedron_Free(table);
    return 0;
fail:
    vrPolyhedron_Free(table);
    return 1;
}

/* The walk reports penetration exactly when the shapes overlap: brute force
 * (0 on contact) and libccd agree, away from grazing contact. */
static int test_walk_penetration_flag_agrees_with_brute_force_and_libccd(void)
{
    int i, j, k, npen = 0, nsep = 0;
    ENSURE(make_shapes() == 0);
    for (i = 0; i < NSHAPES; i++)
        for (j = i; j < NSHAPES; j++) {
            vrShape sa = {VR_SHAPE_POLY, 0, {0, 0, 0}, NULL, 0}, sb = sa;
            vrWalkCache cache;
            memset(&cache, 0, sizeof cache);
            sa.poly = shape[i];
            sb.poly = shape[j];
            for (k = 0; k < 150; k++) {
                vrPose pa, pb;
                vec3 ca, cb, dir, pos;
                int pen, steps, ccd;
                double d, bf, depth = 0;
                random_pair(shape[i], shape[j], 0.2, 1.0, &pa, &pb);
                bf = vrClosest_BruteForce(shape[i], &pa, shape[j], &pb);
                ccd = vrPenetration(&sa, &pa, &sb, &pb, &depth, &dir, &pos) == 0;
                if ((bf > 0 && bf < 1e-6) || (ccd && depth < 1e-6)) continue; /* grazing */
                d = vrClosest_Walk(shape[i], &pa, shape[j], &pb, &cache, &ca, &cb, &steps, &pen);
                ENSURE_MSG(pen == (bf == 0), "%s-%s pose %d: walk %d (d %g), brute force %g", shape_name[i],
                           shape_name[j], k, pen, d, bf);
                ENSURE_MSG(pen == ccd, "%s-%s pose %d: walk %d, libccd %d (depth %g)", shape_name[i], shape_name[j],
                           k, pen, ccd, depth);
                ENSURE(!pen || d <= 0);
                if (pen) npen++; else nsep++;
            }
            ENSURE(cache.fallbacks == 0);
        }
    printf("    %d overlapping, %d separated\n", npen, nsep);
    ENSURE(npen > 500 && nsep > 500);
    return 0;
}

/* reference point distance: signed, negative inside (minus the distance to
 * the nearest face plane) */
static double point_reference(const vrPolyhedron *p, vec3 x)
{
    double best = HUGE_VAL, hmax = -HUGE_VAL;
    int i, k;
    for (i = 0; i < p->nf; i++) {
        double h = vec3_dot(p->face_normal[i], x) - p->face_offset[i];
        int inside = 1, s = p->face_start[i], m = vrPolyhedron_FaceSize(p, i);
        if (h > hmax) hmax = h;
        for (k = 0; k < m; k++) {
            vec3 a = p->vert[p->face_vert[s + k]], b = p->vert[p->face_vert[s + (k + 1) % m]];
            if (vec3_dot(vec3_cross(vec3_sub(b, a), p->face_normal[i]), vec3_sub(x, a)) > 0) inside = 0;
        }
        if (inside && h >= 0 && h < best) best = h;
    }
    if (hmax <= 0) return hmax;
    for (i = 0; i < p->ne; i++) {
        vec3 a = p->vert[p->edge_v[i][0]], b = p->vert[p->edge_v[i][1]], d = vec3_sub(b, a);
        double t = vec3_dot(vec3_sub(x, a), d) / vec3_len2(d), m;
        m = vec3_dist(x, vec3_madd(a, t < 0 ? 0 : t > 1 ? 1 : t, d));
        if (m < best) best = m;
    }
    return best;
}

/* The walk against a point (sphere centres) agrees with the reference
 * inside and outside, from random and from the previous caches. */
static int test_walk_point_matches_reference(void)
{
    int i, k;
    ENSURE(make_shapes() == 0);
    for (i = 0; i < NSHAPES; i++) {
        vrWalkCache warm;
        memset(&warm, 0, sizeof warm);
        for (k = 0; k < 1000; k++) {
            vrPose pa = pose(vec3_make(urange(-1, 1), 0, 0), uquat());
            vec3 x = vec3_madd(pa.p, shape[i]->r_out * urange(0, 1.5), udir()), ca;
            vrWalkCache rnd = random_cache(shape[i], shape[i]);
            double ref = point_reference(shape[i], vrPose_invapply(&pa, x));
            double d1 = vrClosest_WalkPoint(shape[i], &pa, x, &warm, &ca, NULL);
            double d2 = vrClosest_WalkPoint(shape[i], &pa, x, &rnd, &ca, NULL);
            ENSURE_NEAR(d1, ref, 1e-9);
            ENSURE_NEAR(d2, ref, 1e-9);
            ENSURE_NEAR(vec3_dist(ca, x), fabs(ref), 1e-9);
            ENSURE_NEAR(surface_height(shape[i], &pa, ca), 0, 1e-9);
        }
        ENSURE(warm.fallbacks == 0);
    }
    return 0;
}

/* The exhaustive search the walks fall back on past their step cap (never
 * taken in the other tests): brute-force distances, the penetration flag,
 * closest points on the surfaces, and a cache the walk accepts as final. */
static int test_exhaustive_fallback_matches_brute_force(void)
{
    int i, k, npen = 0;
    ENSURE(make_shapes() == 0);
    for (i = 0; i < NSHAPES; i++)
        for (k = 0; k < 60; k++) {
            const vrPolyhedron *a = shape[i], *b = shape[(i + k) % NSHAPES];
            vrPose pa, pb;
            vrWalkCache c;
            vec3 ca, cb, x;
            int pen, steps;
            double d, bf, ref;
            memset(&c, 0, sizeof c);
            random_pair(a, b, 0.3, 1.2, &pa, &pb);
            bf = vrClosest_BruteForce(a, &pa, b, &pb);
            d = vrClosest_Exhaustive(a, &pa, b, &pb, &c, &ca, &cb, &pen);
            if (bf > 0 && bf < 1e-6) continue;
            ENSURE(pen == (bf == 0));
            npen += pen;
            if (pen) continue;
            ENSURE_NEAR(d, bf, 1e-9);
            ENSURE_NEAR(surface_height(a, &pa, ca), 0, 1e-9);
            ENSURE_NEAR(surface_height(b, &pb, cb), 0, 1e-9);
            ENSURE_NEAR(vrClosest_Walk(a, &pa, b, &pb, &c, &ca, &cb, &steps, &pen), bf, 1e-9);
            x = vec3_madd(pa.p, a->r_out * urange(0, 1.5), udir());
            ref = point_reference(a, vrPose_invapply(&pa, x));
            ENSURE_NEAR(vrClosest_ExhaustivePoint(a, &pa, x, &c, &ca), ref, 1e-9);
            ENSURE_NEAR(vec3_dist(ca, x), fabs(ref), 1e-9);
        }
    printf("    %d of them overlapping\n", npen);
    ENSURE(npen > 20);
    return 0;
}

/* Known answers: two unit cubes 0.5 apart face to face, corner to corner
 * along the diagonal, and a stale cache holding out-of-range features. */
static int test_walk_known_distances(void)
{
    vrPolyhedron *c;
    char err[128];
    vrWalkCache cache;
    vec3 ca, cb, diag = vec3_normalize(vec3_make(1, 1, 1));
    vrPose pa = pose(vec3_zero(), quat_identity()), pb = pose(vec3_make(1.5, 0.2, -0.1), quat_identity());
    int steps, pen;
    ENSURE(vrPolyhedron_Cube(vec3_make(0.5, 0.5, 0.5), &c, err, sizeof err) == 0);
    memset(&cache, 0, sizeof cache);
    ENSURE_NEAR(vrClosest_Walk(c, &pa, c, &pb, &cache, &ca, &cb, &steps, &pen), 0.5, 1e-15);
    ENSURE_NEAR(ca.x, 0.5, 1e-15);
    ENSURE_NEAR(cb.x, 1.0, 1e-15);
    ENSURE_NEAR(vrClosest_BruteForce(c, &pa, c, &pb), 0.5, 1e-15);
    pb = pose(vec3_scale(vec3_make(1, 1, 1), 1.0 + 0.3 / sqrt(3.0)), quat_identity());
    cache.a.type = VR_FACE, cache.a.index = 1000, cache.valid = 1; /* stale: ignored */
    ENSURE_NEAR(vrClosest_Walk(c, &pa, c, &pb, &cache, &ca, &cb, &steps, &pen), 0.3, 1e-12);
    ENSURE_NEAR(vec3_dot(vec3_sub(cb, ca), diag), 0.3, 1e-12);
    ENSURE(cache.a.type == VR_VERTEX && cache.b.type == VR_VERTEX);
    vrPolyhedron_Free(c);
    return 0;
}

/* Extreme proportions: a 5 mm plate, a 2 m table against a 1 cm ball mesh,
 * and shapes 1e-12 m apart: no fallback, brute-force distances. */
static int test_walk_is_robust_on_thin_large_and_touching_shapes(void)
{
    vrPolyhedron *plate, *table, *ball;
    char err[128];
    int k, rc = 1, steps;
    ENSURE(vrPolyhedron_Cube(vec3_make(0.3, 0.2, 0.0025), &plate, err, sizeof err) == 0);
    ENSURE(vrPolyhedron_Cube(vec3_make(1, 0.5, 0.025), &table, err, sizeof err) == 0);
    ENSURE(vrPolyhedron_Sphere(0.01, 10, 10, &ball, err, sizeof err) == 0);
    for (k = 0; k < 2000; k++) {
        const vrPolyhedron *a = k % 3 == 0 ? plate : table, *b = k % 3 == 1 ? plate : ball;
        vrPose pa, pb;
        vrWalkCache cache = random_cache(a, b);
        double bf;
        random_pair(a, b, 0.1, 1.0, &pa, &pb);
        bf = vrClosest_BruteForce(a, &pa, b, &pb);
        if (bf <= 1e-6) continue;
        if (check_walk(a, &pa, b, &pb, &cache, bf, &steps)) goto out;
        if (cache.fallbacks) goto out;
    }
    /* 1e-12 apart on a tilted table: the ball's pole, the plate's face */
    for (k = 0; k < 20; k++) {
        const vrPolyhedron *b = k & 1 ? plate : ball;
        double h = k & 1 ? 0.0025 : 0.01;
        vrPose pa = pose(udir(), uquat()), pb;
        vec3 up = vrPose_rotate(&pa, vec3_make(0, 0, 1)), ca, cb;
        vrWalkCache cache = random_cache(table, b);
        int pen;
        double d;
        pb = pose(vec3_madd(vrPose_apply(&pa, vec3_make(0.2, 0.1, 0.025)), h + 1e-12, up), pa.q);
        d = vrClosest_Walk(table, &pa, b, &pb, &cache, &ca, &cb, &steps, &pen);
        if (pen || fabs(d - 1e-12) > 1e-15 || cache.fallbacks) {
            printf("    near-touching %d: d %.17g pen %d\n", k, d, pen);
            goto out;
        }
    }
    rc = 0;
out:
    vrPolyhedron_Free(plate);
    vrPolyhedron_Free(table);
    vrPolyhedron_Free(ball);
    return rc;
}

static void free_shapes(void)
{
    int i;
    for (i = 0; i < NSHAPES; i++) vrPolyhedron_Free(shape[i]);
}

static const vrTest tests[] = {
    TEST(test_walk_known_distances),
    TEST(test_walk_matches_brute_force_on_random_poses),
    TEST(test_walk_is_coherent_along_smooth_motion),
    TEST(test_walk_terminates_on_degenerate_configurations),
    TEST(test_walk_penetration_flag_agrees_with_brute_force_and_libccd),
    TEST(test_walk_point_matches_reference),
    TEST(test_walk_is_robust_on_thin_large_and_touching_shapes),
    TEST(test_exhaustive_fallback_matches_brute_force),
};

const vrTestSuite vrSuite_Closest = {"closest", tests, TEST_COUNT(tests), NULL, free_shapes, 0};
