/* closest_point.c — the closest-feature walk against a point (a sphere's
 * centre): vrClosest_WalkPoint and vrClosest_ExhaustivePoint of closest.h.
 * The walk steps over the Voronoi regions of one polyhedron as closest.c's
 * does over two (V-Clip sec. 5.1); a point beneath a face plane at a local
 * minimum jumps to the face it is farthest above, and inside the
 * polyhedron it ends on the nearest face plane (the exact depth).
 *   point_step        one step
 *   point_exhaustive  the answer by looking at every feature
 *   point_query       the walk, its step cap, the cache
 */
#include "closest.h"
#include "polyhedron.h"
#include "voronoi.h"

/* One step for point x (p's frame).  A face with x beneath its plane is
 * the local-minimum case: either x is inside (every plane above it; *f
 * becomes the nearest face and VR_WALK_DONE) or the walk jumps to the face whose
 * plane x is farthest above. */
static int point_step(const vrPolyhedron *p, vrFeature *f, vec3 x, double tol)
{
    vrFeature nbr;
    double smax;
    if (vrVoronoi_Violation(p, *f, x, tol, &nbr, NULL)) {
        *f = nbr;
        return VR_WALK_GO;
    }
    if (f->type != VR_FACE || vrPolyhedron_FaceHeight(p, f->index, x) >= 0) return VR_WALK_DONE;
    *f = vrFeature_Make(VR_FACE, vrVoronoi_HighestFace(p, x, &smax));
    return smax <= 0 ? VR_WALK_DONE : VR_WALK_GO;
}

/* exhaustive point query: the nearest face plane when inside, else the
 * nearest vertex, edge, or face with x in its prism */
static vrFeature point_exhaustive(const vrPolyhedron *p, vec3 x)
{
    double best;
    int i, g = vrVoronoi_HighestFace(p, x, &best);
    vrFeature f = vrFeature_Make(VR_FACE, g);
    if (best <= 0) return f;
    best = HUGE_VAL;
    for (i = 0; i < p->nv; i++) {
        double d = vec3_dist(x, p->vert[i]);
        if (d < best) best = d, f = vrFeature_Make(VR_VERTEX, i);
    }
    for (i = 0; i < p->ne; i++) {
        double d = vec3_dist(x, vrVoronoi_ClosestOnFeature(p, vrFeature_Make(VR_EDGE, i), x));
        if (d < best) best = d, f = vrFeature_Make(VR_EDGE, i);
    }
    for (i = 0; i < p->nf; i++) {
        double h = vrPolyhedron_FaceHeight(p, i, x);
        if (h >= 0 && h < best && vrVoronoi_InPrism(p, i, x)) best = h, f = vrFeature_Make(VR_FACE, i);
    }
    return f;
}

static double point_query(const vrPolyhedron *a, const vrPose *pa, vec3 point, vrWalkCache *cache, vec3 *ca,
                          int *steps, int at_once)
{
    vec3 x = vrPose_invapply(pa, point), c;
    vrFeature f = vrFeature_Make(VR_VERTEX, 0);
    int n = 0;
    double tol = vrClosest_Tolerance(a->r_out + vec3_maxabs(x));
    if (cache && cache->valid && vrFeature_Valid(a, cache->a)) f = cache->a;
    if (at_once) f = point_exhaustive(a, x);
    while (!at_once && point_step(a, &f, x, tol) == VR_WALK_GO)
        if (++n >= 8 && n >= vrClosest_StepCap(a)) {
            f = point_exhaustive(a, x);
            if (cache) cache->fallbacks++;
            break;
        }
    if (cache) {
        cache->a = f;
        cache->b = vrFeature_Make(VR_VERTEX, 0);
        cache->valid = 1;
    }
    if (steps) *steps = n;
    c = vrVoronoi_ClosestOnFeature(a, f, x);
    if (ca) *ca = vrPose_apply(pa, c);
    if (f.type == VR_FACE) return vrPolyhedron_FaceHeight(a, f.index, x);
    return vec3_dist(x, c);
}

double vrClosest_WalkPoint(const vrPolyhedron *a, const vrPose *pa, vec3 point, vrWalkCache *cache, vec3 *ca,
                           int *steps)
{
    return point_query(a, pa, point, cache, ca, steps, 0);
}

double vrClosest_ExhaustivePoint(const vrPolyhedron *a, const vrPose *pa, vec3 point, vrWalkCache *cache, vec3 *ca)
{
    return point_query(a, pa, point, cache, ca, NULL, 1);
}

