/* primitives.c — the built-in shapes of SPEC 2 as polyhedra: the cube, the
 * sphere mesh and the superquadric (Barr 1981).
 *
 * The cube and the sphere mesh are written down directly, vertices and
 * face loops, and not recentred (they are centred by symmetry); the
 * superquadric is the convex hull (hull.c) of its samples, recentred like
 * any hull.
 *   check_resolution          ures and vres in range
 *   angle_cos_sin             cos and sin of a rational multiple of pi, exact at quarters
 *   signed_pow                Barr's signed power
 *   latlong_samples           the sphere's and the superquadric's sample points
 *   latlong_loops             the sphere mesh's faces
 */
#include <stdlib.h>

#include "hull.h"
#include "primitives.h"

/* ---- cube ------------------------------------------------------------------ */

int vrPolyhedron_Cube(vec3 half, vrPolyhedron **out, char *err, size_t errlen)
{
    /* vertex i has the sign of x from bit 0, y from bit 1, z from bit 2; each
     * face counter-clockwise seen from outside: -x +x -y +y -z +z */
    static const int start[7] = {0, 4, 8, 12, 16, 20, 24};
    static const int loops[24] = {0, 4, 6, 2, 1, 3, 7, 5, 0, 1, 5, 4, 3, 2, 6, 7, 1, 0, 2, 3, 4, 5, 7, 6};
    vec3 v[8];
    int i;
    *out = NULL;
    if (!vec3_isfinite(half) || !(half.x > 0 && half.y > 0 && half.z > 0))
        return vrGeom_Fail(err, errlen, "cube half-extents must be finite and > 0, got (%g, %g, %g)", half.x, half.y,
                           half.z);
    for (i = 0; i < 8; i++)
        v[i] = vec3_make(i & 1 ? half.x : -half.x, i & 2 ? half.y : -half.y, i & 4 ? half.z : -half.z);
    return vrPolyhedron_FromCentredFaces(v, 8, start, loops, 6, VR_COPLANAR_TOL, out, err, errlen);
}

/* ---- sphere and superquadric samples (SPEC 2) ------------------------------ */

static int check_resolution(int ures, int vres, char *err, size_t errlen)
{
    if (ures < 3 || ures > 1000 || vres < 3 || vres > 1000)
        return vrGeom_Fail(err, errlen, "ures and vres must be in 3..1000, got %d and %d", ures, vres);
    return 0;
}

/* cos and sin of num*pi/den, exactly 0 and +-1 at multiples of pi/2; the
 * angles of opposite num are exact negatives, so the samples are symmetric */
static void angle_cos_sin(int num, int den, double *c, double *s)
{
    static const double qc[4] = {1, 0, -1, 0}, qs[4] = {0, 1, 0, -1};
    if ((2 * num) % den == 0) {
        int q = ((2 * num / den) % 4 + 4) % 4;
        *c = qc[q];
        *s = qs[q];
        return;
    }
    *c = cos(num * VR_PI / den);
    *s = sin(num * VR_PI / den);
}

/* Barr's signed power: sign(t) |t|^e, exact 0 at 0 */
static double signed_pow(double t, double e) { return t == 0 || e == 1 ? t : copysign(pow(fabs(t), e), t); }

/* 2 + (vres-1)*ures samples: the south pole, rings of ures points from
 * eta = -pi/2 + pi/vres upwards, the north pole; omega from -pi in steps of
 * 2 pi/ures.  x = a1 C(eta,e1) C(w,e2), y = a2 C(eta,e1) S(w,e2), z = a3 S(eta,e1). */
static vec3 *latlong_samples(double e1, double e2, vec3 r, int ures, int vres)
{
    vec3 *pts = malloc(sizeof *pts * (2 + (size_t)(vres - 1) * ures));
    int k, j, n = 0;
    if (!pts) return NULL;
    pts[n++] = vec3_make(0, 0, -r.z);
    for (k = 1; k < vres; k++) {
        double ce, se;
        angle_cos_sin(2 * k - vres, 2 * vres, &ce, &se);
        for (j = 0; j < ures; j++) {
            double cw, sw, ring = signed_pow(ce, e1);
            angle_cos_sin(2 * j - ures, ures, &cw, &sw);
            pts[n++] = vec3_make(r.x * ring * signed_pow(cw, e2), r.y * ring * signed_pow(sw, e2),
                                 r.z * signed_pow(se, e1));
        }
    }
    pts[n] = vec3_make(0, 0, r.z);
    return pts;
}

/* the sphere mesh's faces: triangle fans at the poles, quads between rings,
 * counter-clockwise seen from outside (omega grows to the right) */
static void latlong_loops(int ures, int vres, int *start, int *loop)
{
    int k, j, f = 0, n = 0, top = 1 + (vres - 1) * ures;
#define RING(k, j) (1 + ((k) - 1) * ures + (j) % ures)
    for (j = 0; j < ures; j++) {
        start[f++] = n;
        loop[n++] = 0;
        loop[n++] = RING(1, j + 1);
        loop[n++] = RING(1, j);
    }
    for (k = 1; k + 1 < vres; k++)
        for (j = 0; j < ures; j++) {
            start[f++] = n;
            loop[n++] = RING(k, j);
            loop[n++] = RING(k, j + 1);
            loop[n++] = RING(k + 1, j + 1);
            loop[n++] = RING(k + 1, j);
        }
    for (j = 0; j < ures; j++) {
        start[f++] = n;
        loop[n++] = RING(vres - 1, j);
        loop[n++] = RING(vres - 1, j + 1);
        loop[n++] = top;
    }
#undef RING
    start[f] = n;
}

int vrPolyhedron_Sphere(double radius, int ures, int vres, vrPolyhedron **out, char *err, size_t errlen)
{
    int nf = ures * vres, rc, v;
    vec3 *pts;
    int *start, *loop;
    *out = NULL;
    if (!(radius > 0) || !isfinite(radius))
        return vrGeom_Fail(err, errlen, "sphere radius must be finite and > 0, got %g", radius);
    if (check_resolution(ures, vres, err, errlen) != 0) return -1;
    pts = latlong_samples(1, 1, vec3_make(radius, radius, radius), ures, vres);
    start = malloc(sizeof *start * (nf + 1));
    loop = malloc(sizeof *loop * 4 * nf);
    if (!pts || !start || !loop) {
        rc = vrGeom_Fail(err, errlen, "out of memory");
    } else {
        latlong_loops(ures, vres, start, loop);
        /* symmetric under z -> -z and a turn of 2 pi/ures about z: centred */
        rc = vrPolyhedron_FromCentredFaces(pts, 2 + (vres - 1) * ures, start, loop, nf, VR_COPLANAR_TOL, out, err,
                                           errlen);
    }
    if (rc == 0) /* drawn as the sphere it stands for */
        /* NOLINTNEXTLINE(clang-analyzer-core.NullDereference): rc is vrGeom_Fail's -1 whenever *out is not made */
        for (v = 0; v < (*out)->nv; v++) (*out)->vert_normal[v] = vec3_normalize((*out)->vert[v]);
    free(pts);
    free(start);
    free(loop);
    return rc;
}

/* Smooth normals are the area-weighted face normals of the hull (merged
 * flats then shade flat), not Barr's analytic normal, which is singular
 * where the exponents make edges. */
int vrPolyhedron_Superquadric(double exp1, double exp2, vec3 radii, int ures, int vres, vrPolyhedron **out,
                              char *err, size_t errlen)
{
    vec3 *pts;
    int rc;
    *out = NULL;
    if (!(exp1 >= 0.05 && exp1 <= 2 && exp2 >= 0.05 && exp2 <= 2))
        return vrGeom_Fail(err, errlen, "superquadric exponents must be in 0.05..2, got %g and %g", exp1, exp2);
    if (!vec3_isfinite(radii) || !(radii.x > 0 && radii.y > 0 && radii.z > 0))
        return vrGeom_Fail(err, errlen, "superquadric radii must be finite and > 0, got (%g, %g, %g)", radii.x,
                           radii.y, radii.z);
    if (check_resolution(ures, vres, err, errlen) != 0) return -1;
    pts = latlong_samples(exp1, exp2, radii, ures, vres);
    if (!pts) return vrGeom_Fail(err, errlen, "out of memory");
    rc = vrPolyhedron_Hull(pts, 2 + (vres - 1) * ures, out, err, errlen);
    free(pts);
    return rc;
}
