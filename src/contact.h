/* contact.h — distance, normal and contact region of a pair of posed shapes
 * (SPEC 2, thesis 3.2.1): what the owner (gp.c), the rest test and the
 * bodies use.
 *
 * The walk (closest.h, Lin–Canny / V-Clip) only FINDS the closest features,
 * starting from the pair's cached features.  What this module returns is a
 * pure function of the two shapes and their poses, never of where the cache
 * started or which feature the walk ended on: distances and normals are
 * recomputed from canonical support features (canonical.c).  Determinism
 * between heap on/off and between serial and parallel runs depends on it.
 *
 * The pair is always evaluated with the lower-indexed object as `a`.
 *
 * The canonical rule (canonical.c): from the walk's direction, each body's
 * near-support set (vertices within 1e-9 m of its supporting plane) is a
 * vertex, an edge or a face; the normal is a's face normal, else minus b's,
 * else edge x edge, else the closest points of the two features; the
 * distance follows from the same features.  Spheres are true spheres
 * (sphere.c).
 *
 * No static state: any number of threads or processes may query different
 * pairs at once (a cache belongs to one pair and one caller at a time).
 */
#ifndef VROC_CONTACT_H
#define VROC_CONTACT_H

#include <stddef.h> /* NULL: caches and outputs that may be NULL */

#include "closest.h"
#include "region.h"
#include "shape.h"

typedef struct vrContact {
    double dist;     /* separation distance; <= 0: penetration, dist = -depth */
    vec3 n;          /* unit normal pointing from a toward b (moving b along +n separates) */
    vec3 pa, pb;     /* closest points on a and b (world), pb - pa = dist n up to rounding.
                        When a face is involved the closest points are not unique: the
                        other body's support feature's centroid and its projection on the
                        face (it may lie off the face when the faces overhang: use the
                        region).  On penetration both are the contact position (libccd's,
                        or for a sphere midway between the deepest points). */
    int npoints;     /* contact region points (only filled by vrContact_Region) */
    vec3 point[VR_REGION_MAX];
    double gap[VR_REGION_MAX];  /* each point's gap along n between the two surfaces (>= dist) */
    int walk_steps;  /* feature changes the walk made in this query (0 for closed forms) */
} vrContact;

/* Distance, normal and closest points; npoints = 0.  cache may be NULL (then
 * every query starts cold).  Returns 0, or -1 when out of memory or given a
 * box/poly shape without a polyhedron. */
int vrContact_Distance(const vrShape *a, const vrPose *pa, const vrShape *b, const vrPose *pb,
                       vrWalkCache *cache, vrContact *out);

/* As vrContact_Distance (same dist, n, pa, pb to the bit), and when
 * out->dist <= d also the contact region of SPEC 2: points on the contact
 * plane (world coordinates, midway between the bodies' support planes).  The
 * vertices of each body within d + 1e-9 of the other's support plane,
 * projected along n, hulled, and intersected (1e-9 m tolerance): a face-face
 * pair gives the clipped overlap of the faces, a vertex-face pair the vertex,
 * edge-face the clipped edge, crossing edges their crossing point.  A sphere
 * against anything gives one point: the sphere's closest point (two spheres:
 * the midpoint of their closest points).  Penetration gives one point, the
 * contact position.  Never more than VR_REGION_MAX points (a larger overlap is
 * reduced to its extreme corners in VR_REGION_MAX directions).  d < 0 is
 * taken as 0. */
int vrContact_Region(const vrShape *a, const vrPose *pa, const vrShape *b, const vrPose *pb,
                     double d, vrWalkCache *cache, vrContact *out);

/* The walk's own distance and unit direction a -> b for two polyhedra:
 * exact up to rounding, but its last bits may depend on where the cache
 * started.  For decisions clearly away from a threshold (a caller allows a
 * tolerance far above rounding) and for schedule keys; never for anything
 * whose bits must not depend on the cache.  Returns -1 for spheres (their
 * closed forms are as cheap), without a cache, or when the shapes may
 * touch: use vrContact_Distance then. */
int vrContact_Quick(const vrShape *a, const vrPose *pa, const vrShape *b, const vrPose *pb,
                    vrWalkCache *cache, double *dist, vec3 *n);

/* Shapes into each other no deeper than this (m) are taken as touching
 * along the face normal they overlap least along, with their whole
 * contact region, not libccd's one point (contact.c): bodies resting on
 * each other may sink this far (SPEC 7). */
#define VR_SHALLOW_OVERLAP 1e-4

/* How far from a threshold the walk's distance may decide: over a thousand
 * times the largest difference from vrContact_Distance the tests find on
 * random poses (6e-15 m, objects up to 20 m from the origin; they fail
 * above 1e-13).  Above a threshold the walk's own slack is added
 * (contact.c above_walk_slack): near a face a hair off parallel to an
 * edge, where it stops depends on its start. */
#define VR_QUICK_TOL 1e-11

/* How far below the walk's distance a look that only wants to know that a
 * pair is clear of the envelope (cheap_look.c, quiet.c, the look-ahead's
 * may_cross) takes the canonical one to be.  It was the canonical rule's
 * error where a face lies within 1e-9 m of parallel to a long edge or a
 * larger face, measured at that feature's far ends (a table's 6 m edge
 * under a tilted 9 cm box face: 8e-11 m; a 6 mm facet against a 6 m edge
 * could give 1e-6 m).  Now that only the part under the face is measured
 * (overhang.c), the two differ by the walk's slack (1e-12 m per metre of
 * the pair's size); the margin stays this wide because it costs nothing
 * measurable (1e-9 m instead: 0.1 % fewer instructions in the peers'
 * rooms, the same bits). */
#define VR_QUICK_CLEAR 1e-5

/* A canonical distance this little below a level is at the level: the
 * bisection stops at the first halving found there (bisect.c).  Half the
 * distance bounds' tolerance, so no bound ever decides such a halving:
 * every run measures it, whatever it measured before. */
#define VR_AT_LEVEL 5e-13

/* Is the distance <= d?  The walk's own distance decides when it is more
 * than VR_QUICK_TOL below d or VR_QUICK_TOL and its slack above it (the
 * canonical answer is then the same, whatever the walk's start), else
 * vrContact_Distance's, finished from the same walk: the bisection's test
 * (SPEC 3.2), one walk a call.  2 when the canonical distance is at d (no
 * more than VR_AT_LEVEL below it).  seen (may be NULL) gets what was measured:
 * dist, and closest points pa, pb that are points of the bodies (the
 * walk's for polyhedra, which may differ from vrContact_Distance's in the
 * last bits or, for parallel faces, in place); dist <= 0 when the shapes
 * touch or overlap. */
int vrContact_Within(const vrShape *a, const vrPose *pa, const vrShape *b, const vrPose *pb,
                     vrWalkCache *cache, double d, vrContact *seen);

#endif
