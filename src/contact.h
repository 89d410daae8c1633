/* contact.h — distance, normal and contact region of a pair of posed shapes
 * (SPEC 2, thesis 3.2.1).
 *
 * The walk (closest.c, Lin–Canny / V-Clip) only FINDS the closest features,
 * starting from the pair's cached features.  What this module returns is a
 * pure function of the two shapes and their poses, never of where the cache
 * started or which feature the walk ended on: distances and normals are
 * recomputed from canonical support features (see contact.c).  Determinism
 * between heap on/off and between serial and parallel runs depends on it.
 *
 * The pair is always evaluated with the lower-indexed object as `a`.
 */
#ifndef VROC_CONTACT_H
#define VROC_CONTACT_H

#include "polyhedron.h"

typedef enum { VR_SHAPE_SPHERE, VR_SHAPE_BOX, VR_SHAPE_POLY } vrShapeKind;

/* What collides.  A sphere collides as a true sphere (its mesh is only for
 * drawing); a box is a polyhedron with closed forms against spheres. */
typedef struct vrShape {
    vrShapeKind kind;
    double radius;              /* sphere */
    vec3 half;                  /* box half extents */
    const vrPolyhedron *poly;   /* box and poly: the hull, body frame */
} vrShape;

typedef struct vrFeature { int type; int index; } vrFeature; /* VR_VERTEX / VR_EDGE / VR_FACE */

/* Per-pair memory of the walk: where the last query ended.  All zero bytes
 * is a valid "start anywhere" state. */
typedef struct vrWalkCache { vrFeature a, b; int valid; } vrWalkCache;

#define VR_REGION_MAX 64

typedef struct vrContact {
    double dist;     /* separation distance; <= 0: penetration, dist = -depth */
    vec3 n;          /* unit normal pointing from a toward b */
    vec3 pa, pb;     /* closest points on a and b (world); on penetration both are libccd's contact position */
    int npoints;     /* contact region points (only filled by vrContact_Region) */
    vec3 point[VR_REGION_MAX];
    int walk_steps;  /* feature changes the walk made in this query */
} vrContact;

/* Distance, normal and closest points.  Returns 0, or -1 on a degenerate
 * input it cannot handle (never expected for valid shapes). */
int vrContact_Distance(const vrShape *a, const vrPose *pa, const vrShape *b, const vrPose *pb,
                       vrWalkCache *cache, vrContact *out);

/* As vrContact_Distance, and when out->dist <= d also the contact region of
 * SPEC 2: points on the contact plane (world coordinates, midway between the
 * bodies along n).  A face–face pair gives the clipped overlap of the faces, a
 * vertex–face pair the vertex, edge–face the clipped edge, sphere the closest
 * point.  Never more than VR_REGION_MAX points (a larger overlap is reduced
 * to VR_REGION_MAX of its corners, keeping its convex hull's extremes). */
int vrContact_Region(const vrShape *a, const vrPose *pa, const vrShape *b, const vrPose *pb,
                     double d, vrWalkCache *cache, vrContact *out);

/* Penetration depth and direction by libccd (penetration.c): called by the
 * above when the shapes overlap; exposed for tests.  Returns 0 when they
 * overlap (depth >= 0, dir from a toward b, pos a point in the overlap),
 * -1 when they do not. */
int vrPenetration(const vrShape *a, const vrPose *pa, const vrShape *b, const vrPose *pb,
                  double *depth, vec3 *dir, vec3 *pos);

/* The closest-feature walk itself (closest.c).  Returns the distance between
 * the features it ends on (<= 0 and *penetrating = 1 when it finds the
 * polyhedra overlapping), the closest points, and the number of feature
 * steps taken.  `b_point` non-NULL walks against a single point instead of
 * polyhedron b (sphere centres). */
double vrClosest_Walk(const vrPolyhedron *a, const vrPose *pa, const vrPolyhedron *b, const vrPose *pb,
                      vrWalkCache *cache, vec3 *ca, vec3 *cb, int *steps, int *penetrating);
double vrClosest_WalkPoint(const vrPolyhedron *a, const vrPose *pa, vec3 point,
                           vrWalkCache *cache, vec3 *ca, int *steps);

/* Reference distance by brute force over all feature pairs (tests only). */
double vrClosest_BruteForce(const vrPolyhedron *a, const vrPose *pa, const vrPolyhedron *b, const vrPose *pb);

#endif
