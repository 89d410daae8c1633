/* test_mass.c — volume, centre and inertia against closed forms (SPEC 2). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "hull.h"
#include "mass.h"
#include "off.h"
#include "primitives.h"
#include "test.h"

static char err[512];

static double rel(double got, double want) { return fabs(got - want) / fabs(want); }

/* the largest |a - b| over the entries, against the largest |b| */
static double mat_rel(const mat33 *a, const mat33 *b)
{
    double d = 0, m = 0;
    int i, j;
    for (i = 0; i < 3; i++)
        for (j = 0; j < 3; j++) {
            d = fmax(d, fabs(a->m[i][j] - b->m[i][j]));
            m = fmax(m, fabs(b->m[i][j]));
        }
    return d / m;
}

static int test_box_mass_matches_the_closed_form(void)
{
    vrPolyhedron *p;
    double a = 0.5, b = 2, c = 3;
    mat33 want = mat33_diag((b * b + c * c) / 3, (a * a + c * c) / 3, (a * a + b * b) / 3); /* m(b^2+c^2)/3 for half sizes */
    ENSURE(vrPolyhedron_Cube(vec3_make(a, b, c), &p, err, sizeof err) == 0);
    ENSURE_NEAR(p->volume, 8 * a * b * c, 1e-14);
    ENSURE_MSG(mat_rel(&p->inertia_unit, &want) < 1e-15, "%g", mat_rel(&p->inertia_unit, &want));
    ENSURE(p->inertia_unit.m[0][1] == 0 && p->inertia_unit.m[0][2] == 0 && p->inertia_unit.m[1][2] == 0);
    vrPolyhedron_Free(p);
    return 0;
}

/* thesis 3.3.1.1: inscribed radius the nearest face, circumscribed the farthest corner */
static int test_box_inner_and_outer_radius(void)
{
    vrPolyhedron *p;
    ENSURE(vrPolyhedron_Cube(vec3_make(1, 2, 3), &p, err, sizeof err) == 0);
    ENSURE_NEAR(p->r_in, 1, 1e-15);
    ENSURE_NEAR(p->r_out, sqrt(14), 1e-15);
    vrPolyhedron_Free(p);
    ENSURE(vrPolyhedron_Sphere(2, 40, 40, &p, err, sizeof err) == 0);
    ENSURE_NEAR(p->r_out, 2, 1e-15);
    ENSURE(p->r_in < 2 && p->r_in > 2 * cos(VR_PI / 40) * cos(VR_PI / 40) - 1e-12);
    vrPolyhedron_Free(p);
    return 0;
}

/* relative errors of volume and of Ixx, Izz of a tessellated ellipsoid
 * (exponents 1) against V = 4/3 pi abc, Ixx = m (b^2 + c^2)/5 */
static int ellipsoid_errors(vec3 r, int res, int sphere, double *ev, double *ei)
{
    vrPolyhedron *p;
    double v = 4.0 / 3.0 * VR_PI * r.x * r.y * r.z;
    if (sphere)
        ENSURE(vrPolyhedron_Sphere(r.x, res, res, &p, err, sizeof err) == 0);
    else
        ENSURE(vrPolyhedron_Superquadric(1, 1, r, res, res, &p, err, sizeof err) == 0);
    *ev = rel(p->volume, v);
    *ei = fmax(rel(p->inertia_unit.m[0][0], (r.y * r.y + r.z * r.z) / 5),
               rel(p->inertia_unit.m[2][2], (r.x * r.x + r.y * r.y) / 5));
    ENSURE(fabs(p->inertia_unit.m[0][1]) < 1e-12 && fabs(p->inertia_unit.m[1][2]) < 1e-12);
    vrPolyhedron_Free(p);
    return 0;
}

/* the error falls about fourfold each time the resolution doubles */
static int converges(vec3 r, int sphere)
{
    static const int res[] = {10, 20, 40, 80, 160};
    double lastv = 1, lasti = 1;
    int k;
    for (k = 0; k < 5; k++) {
        double ev, ei;
        ENSURE(ellipsoid_errors(r, res[k], sphere, &ev, &ei) == 0);
        ENSURE_MSG(ev < lastv / 3 && ei < lasti / 3, "%dx%d: volume %.3g (was %.3g), inertia %.3g (was %.3g)",
                   res[k], res[k], ev, lastv, ei, lasti);
        lastv = ev;
        lasti = ei;
    }
    ENSURE_MSG(lastv < 5e-4 && lasti < 5e-4, "%g %g", lastv, lasti);
    return 0;
}

static int test_sphere_mesh_mass_converges_to_the_ball(void)
{
    return converges(vec3_make(1.3, 1.3, 1.3), 1);
}

static int test_superquadric_with_exponents_1_converges_to_the_ellipsoid(void)
{
    return converges(vec3_make(1, 2, 3), 0);
}

/* ---- an OFF tetrahedron, turned and moved --------------------------------- */

/* a tetrahedron's inertia about its centroid per unit mass, by hand:
 * the covariance of a uniform tetrahedron is sum_k q_k q_k^T / 20 (q_k the
 * corners about the centroid), and I = tr(C) E - C */
static mat33 tetra_inertia(const vec3 *q4, vec3 *centroid)
{
    vec3 c = vec3_scale(vec3_add(vec3_add(q4[0], q4[1]), vec3_add(q4[2], q4[3])), 0.25);
    mat33 cov = mat33_zero(), r;
    int k, i, j;
    for (k = 0; k < 4; k++) {
        vec3 q = vec3_sub(q4[k], c);
        for (i = 0; i < 3; i++)
            for (j = 0; j < 3; j++) cov.m[i][j] += vec3_get(q, i) * vec3_get(q, j) / 20;
    }
    for (i = 0; i < 3; i++)
        for (j = 0; j < 3; j++) r.m[i][j] = (i == j ? cov.m[0][0] + cov.m[1][1] + cov.m[2][2] : 0) - cov.m[i][j];
    *centroid = c;
    return r;
}

static int test_off_tetrahedron_centroid_and_inertia_match_the_hand_formula(void)
{
    static const double corner[4][3] = {{0, 0, 0}, {2, 0, 0}, {0.5, 1.5, 0}, {0.3, 0.4, 1.1}};
    quat q = quat_normalize(quat_make(0.9, 0.2, -0.3, 0.25));
    mat33 R = mat33_from_quat(q), want;
    vec3 v[4], t = vec3_make(3, -7, 11), c;
    char path[] = "/tmp/vroc-tetra-XXXXXX";
    int fd = mkstemp(path), k;
    FILE *f = fd >= 0 ? fdopen(fd, "w") : NULL;
    vrPolyhedron *p;
    double vol;
    ENSURE(f != NULL);
    fprintf(f, "OFF\n4 4 6\n");
    for (k = 0; k < 4; k++) {
        v[k] = vec3_add(mat33_mulv(&R, vec3_make(corner[k][0], corner[k][1], corner[k][2])), t);
        fprintf(f, "%.17g %.17g %.17g\n", v[k].x, v[k].y, v[k].z);
    }
    fprintf(f, "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n");
    fclose(f);
    ENSURE_MSG(vrPolyhedron_FromOFF(path, &p, err, sizeof err) == 0, "%s", err);
    unlink(path);
    want = tetra_inertia(v, &c);
    vol = fabs(vec3_dot(vec3_sub(v[1], v[0]), vec3_cross(vec3_sub(v[2], v[0]), vec3_sub(v[3], v[0])))) / 6;
    ENSURE_NEAR(p->volume, vol, 1e-14);
    ENSURE_MSG(vec3_dist(p->shift, c) < 1e-14, "shift (%g %g %g)", p->shift.x, p->shift.y, p->shift.z);
    ENSURE_MSG(mat_rel(&p->inertia_unit, &want) < 1e-13, "%g", mat_rel(&p->inertia_unit, &want));
    ENSURE(fabs(want.m[0][1]) > 1e-3); /* turned: the products of inertia matter */
    vrPolyhedron_Free(p);
    return 0;
}

/* ---- principal axes ------------------------------------------------------- */

static int test_principal_axes_of_a_turned_box_recover_its_sizes(void)
{
    double h[3] = {0.3, 1.1, 2.0}; /* ascending half sizes: descending moments */
    quat q = quat_normalize(quat_make(0.3, -0.5, 0.7, 0.4));
    mat33 R = mat33_from_quat(q), axes;
    vec3 pts[8], m;
    vrPolyhedron *p;
    int i, k;
    for (i = 0; i < 8; i++)
        pts[i] = mat33_mulv(&R, vec3_make(i & 1 ? h[0] : -h[0], i & 2 ? h[1] : -h[1], i & 4 ? h[2] : -h[2]));
    ENSURE(vrPolyhedron_Hull(pts, 8, &p, err, sizeof err) == 0);
    vrMass_Principal(&p->inertia_unit, &m, &axes);
    ENSURE(m.x <= m.y && m.y <= m.z);
    ENSURE_NEAR(mat33_det(&axes), 1, 1e-12);
    /* I_i = (h_j^2 + h_k^2)/3, so h_i^2 = 3 (I_j + I_k - I_i) / 2 */
    for (k = 0; k < 3; k++) {
        double mi = vec3_get(m, k), mj = vec3_get(m, (k + 1) % 3), mk = vec3_get(m, (k + 2) % 3);
        vec3 axis = mat33_col(&axes, k), box_axis = mat33_col(&R, 2 - k);
        ENSURE_NEAR(sqrt(1.5 * (mj + mk - mi)), h[2 - k], 1e-12);
        ENSURE_NEAR(fabs(vec3_dot(axis, box_axis)), 1, 1e-12);
    }
    vrPolyhedron_Free(p);
    return 0;
}

/* A = V diag V^T for a rotation V and ascending moments, even when two
 * moments are equal or the matrix is already diagonal */
static int principal_reconstructs(const mat33 *a)
{
    vec3 m;
    mat33 v, d, vd, vt, back;
    vrMass_Principal(a, &m, &v);
    d = mat33_diag(m.x, m.y, m.z);
    vd = mat33_mul(&v, &d);
    vt = mat33_transpose(&v);
    back = mat33_mul(&vd, &vt);
    ENSURE(m.x <= m.y && m.y <= m.z);
    ENSURE_NEAR(mat33_det(&v), 1, 1e-12);
    ENSURE_MSG(mat_rel(&back, a) < 1e-13, "%g", mat_rel(&back, a));
    return 0;
}

static int test_principal_handles_diagonal_repeated_and_negative_determinant_cases(void)
{
    mat33 r = mat33_from_quat(quat_normalize(quat_make(0.1, 0.9, -0.2, 0.3))), rt = mat33_transpose(&r);
    mat33 d = mat33_diag(2, 2, 5), rd = mat33_mul(&r, &d), turned = mat33_mul(&rd, &rt);
    mat33 swapped = mat33_diag(3, 1, 2), ident = mat33_identity(), zero = mat33_zero();
    ENSURE(principal_reconstructs(&turned) == 0);
    ENSURE(principal_reconstructs(&swapped) == 0);
    vec3 m;
    mat33 v;
    ENSURE(principal_reconstructs(&ident) == 0);
    vrMass_Principal(&zero, &m, &v); /* nothing to compare a reconstruction with */
    ENSURE(m.x == 0 && m.y == 0 && m.z == 0 && mat33_det(&v) == 1);
    return 0;
}

/* ---- volume and centroid of any closed polyhedron --------------------------- */

static int test_volume_centroid_follows_the_vertices_anywhere(void)
{
    vrPolyhedron *p;
    vec3 t = vec3_make(1e3, -250, 42.5), c;
    double vol;
    int v;
    ENSURE(vrPolyhedron_Superquadric(0.5, 1.5, vec3_make(1, 2, 0.7), 13, 9, &p, err, sizeof err) == 0);
    vrMass_VolumeCentroid(p, &vol, &c);
    ENSURE_NEAR(vol, p->volume, 1e-13 * vol);
    ENSURE(vec3_len(c) < 1e-14); /* built on its centre of mass */
    for (v = 0; v < p->nv; v++) p->vert[v] = vec3_add(p->vert[v], t);
    vrMass_VolumeCentroid(p, &vol, &c);
    ENSURE_NEAR(vol, p->volume, 1e-11 * vol);
    ENSURE_MSG(vec3_dist(c, t) < 1e-11, "(%g %g %g)", c.x - t.x, c.y - t.y, c.z - t.z);
    vrPolyhedron_Free(p);
    return 0;
}

static const vrTest tests[] = {
    TEST(test_box_mass_matches_the_closed_form),
    TEST(test_box_inner_and_outer_radius),
    TEST(test_sphere_mesh_mass_converges_to_the_ball),
    TEST(test_superquadric_with_exponents_1_converges_to_the_ellipsoid),
    TEST(test_off_tetrahedron_centroid_and_inertia_match_the_hand_formula),
    TEST(test_principal_axes_of_a_turned_box_recover_its_sizes),
    TEST(test_principal_handles_diagonal_repeated_and_negative_determinant_cases),
    TEST(test_volume_centroid_follows_the_vertices_anywhere),
};

const vrTestSuite vrSuite_Mass = {"mass", tests, TEST_COUNT(tests), NULL, NULL, 0};
