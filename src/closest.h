/* closest.h — the closest-feature walk (closest.c, V-Clip form of
 * Lin–Canny) and its per-pair cache.  It only FINDS the closest features of
 * two convex polyhedra (or of a polyhedron and a point); the distance and
 * normal whose bits must not depend on the cache are contact.c's. */
#ifndef VROC_CLOSEST_H
#define VROC_CLOSEST_H

#include "feature.h"

/* Per-pair memory of the walk: where the last query ended.  All zero bytes
 * is a valid "start anywhere" state (vertex 0 / vertex 0); so is any stale or
 * out-of-range content.  Only speed depends on it, never a result.
 * `fallbacks` counts queries that ended by exhaustive search: the walk hit
 * its step cap, or the plane between its closest points did not separate
 * the bodies that far (closest.c, separated); expected 0, tests check it. */
typedef struct vrWalkCache { vrFeature a, b; int valid; unsigned fallbacks; } vrWalkCache;

/* The closest-feature walk itself (closest.c, V-Clip).  Returns the distance
 * between the features it ends on, the closest points ca, cb (world), and the
 * number of feature steps taken; when it finds the polyhedra overlapping,
 * *penetrating = 1, the result is <= 0 (not a depth: use vrPenetration) and
 * ca = cb is a point of the overlap.  cache may be NULL (start at vertex
 * 0 / vertex 0); ca, cb, steps, penetrating may be NULL.  The features it
 * ends on are left in the cache: in degenerate ties (parallel faces) they
 * depend on where it started, the distance does not.
 *
 * vrClosest_WalkPoint walks polyhedron a against a point (sphere centres):
 * the distance, or when the point is inside minus its distance to the
 * nearest face plane (the exact depth of a point), and the closest point ca
 * of a's surface (may be NULL).  The cache's `a` holds a's feature. */
double vrClosest_Walk(const vrPolyhedron *a, const vrPose *pa, const vrPolyhedron *b, const vrPose *pb,
                      vrWalkCache *cache, vec3 *ca, vec3 *cb, int *steps, int *penetrating);
double vrClosest_WalkPoint(const vrPolyhedron *a, const vrPose *pa, vec3 point,
                           vrWalkCache *cache, vec3 *ca, int *steps);

/* What the walks do when they hit their step cap (counted in
 * cache->fallbacks): search every feature pair that can matter, O(E F);
 * same results and cache update.  Exposed so that tests can check this
 * rarely taken path; ..._All searches every pair (the tests' reference). */
double vrClosest_Exhaustive(const vrPolyhedron *a, const vrPose *pa, const vrPolyhedron *b, const vrPose *pb,
                            vrWalkCache *cache, vec3 *ca, vec3 *cb, int *penetrating);
double vrClosest_ExhaustiveAll(const vrPolyhedron *a, const vrPose *pa, const vrPolyhedron *b, const vrPose *pb,
                               vrWalkCache *cache, vec3 *ca, vec3 *cb, int *penetrating);
double vrClosest_ExhaustivePoint(const vrPolyhedron *a, const vrPose *pa, vec3 point, vrWalkCache *cache, vec3 *ca);

/* for the walks (closest.c, closest_point.c): a plane's slack in region
 * tests, relative to the scale of the pair (m); a step's outcome; the
 * step cap past which the exhaustive search answers */
#define VR_REGION_TOL 1e-12
/* the walks' slack for a pair (or a body and a point) of this size: its
 * outer radii and the offset between them, in metres */
static inline double vrClosest_Tolerance(double size) { return VR_REGION_TOL * (size > 1 ? size : 1); }
enum { VR_WALK_GO, VR_WALK_DONE };
static inline int vrClosest_StepCap(const vrPolyhedron *p) { return 2 * (p->nv + p->ne + p->nf); }

#endif
