/* penetration.c — depth, direction and position of overlapping shapes, by
 * libccd's Minkowski Portal Refinement (SPEC 3.1: "libccd (MPR, or GJK+EPA)
 * gives depth and direction").  libccd has no separation distance: the walk
 * (closest.c) covers separated shapes, this file the overlap.
 *
 * Shapes reach libccd through support functions: the true sphere
 * analytically, polyhedra (boxes included) by the farthest hull vertex, the
 * lowest index winning ties (shape.c: a scan, or a climb from the last
 * one's vertex that finds the scan's answer), so the result is a pure
 * function of shapes and poses.  MPR is deterministic and exact for
 * two spheres; for polyhedra it gives the depth along the portal it refines
 * from the centre line, not always the minimum translation.
 */
#include <ccd/ccd.h>

#include "penetration.h"

/* the MPR stopping tolerance (m); libccd's default 1e-4 is coarse for 1 cm
 * objects */
#define MPR_TOL 1e-9
#define MPR_MAX_ITER 1000

typedef struct CcdObject { const vrShape *shape; const vrPose *pose; int *hint; } CcdObject;

static vec3 from_ccd(const ccd_vec3_t *v) { return vec3_make(v->v[0], v->v[1], v->v[2]); }
static void to_ccd(vec3 a, ccd_vec3_t *v) { ccdVec3Set(v, a.x, a.y, a.z); }

static void support(const void *obj, const ccd_vec3_t *dir, ccd_vec3_t *out)
{
    const CcdObject *o = obj;
    to_ccd(vrShape_SupportFrom(o->shape, o->pose, from_ccd(dir), o->hint), out);
}

/* bodies are built around their centre of mass: the pose origin */
static void centre(const void *obj, ccd_vec3_t *out) { to_ccd(((const CcdObject *)obj)->pose->p, out); }

int vrPenetration(const vrShape *a, const vrPose *pa, const vrShape *b, const vrPose *pb,
                  double *depth, vec3 *dir, vec3 *pos)
{
    CcdObject oa, ob;
    int hint[2] = {-1, -1};    /* each climb starts where the shape's last one ended */
    ccd_t ccd;
    ccd_real_t dp;
    ccd_vec3_t d, p;
    oa.shape = a;
    oa.pose = pa;
    oa.hint = &hint[0];
    ob.shape = b;
    ob.pose = pb;
    ob.hint = &hint[1];
    CCD_INIT(&ccd);
    ccd.support1 = ccd.support2 = support;
    ccd.center1 = ccd.center2 = centre;
    ccd.max_iterations = MPR_MAX_ITER;
    ccd.mpr_tolerance = MPR_TOL;
    if (ccdMPRPenetration(&oa, &ob, &ccd, &dp, &d, &p) != 0) return -1;
    /* libccd: translating b by depth along dir separates them, so dir points
     * from a toward b (checked by test_penetration_direction_points_from_a_to_b) */
    *depth = dp;
    *dir = vec3_normalize(from_ccd(&d));
    *pos = from_ccd(&p);
    return 0;
}
