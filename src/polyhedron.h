/* polyhedron.h — building a convex polyhedron's feature graph from its faces
 * (SPEC 2), freeing it, and the climb over it; the helpers the geometry
 * builders share (hull.c, off.c, primitives.c).  The type is in feature.h.
 *
 * Builders return 0 and set *out, or return -1 with a message in err
 * (NUL-terminated, at most errlen bytes) and leave *out NULL.  None prints.
 */
#ifndef VROC_POLYHEDRON_H
#define VROC_POLYHEDRON_H

#include <stddef.h>
#include "feature.h"

/* relative tolerance (of the shape's size, the diagonal of its bounding
 * box) within which facets count as coplanar (SPEC 2) */
#define VR_COPLANAR_TOL 1e-9

/* A polyhedron from its vertices and the boundary loops of its faces
 * (counter-clockwise seen from outside, convex, every vertex used, closed
 * 2-manifold): centres it on its centre of mass, computes planes, the feature
 * graph, area-weighted smooth normals and the mass properties.  Refuses a
 * surface that is not closed, not planar or not convex within tol (relative). */
int vrPolyhedron_FromFaces(const vec3 *vert, int nv, const int *face_start, const int *face_vert, int nf,
                           double tol, vrPolyhedron **out, char *err, size_t errlen);
/* The same for vertices whose centre of mass is the origin by symmetry
 * (the cube, the sphere mesh): not recentred, as the computed centre would
 * only add rounding to every vertex. */
int vrPolyhedron_FromCentredFaces(const vec3 *vert, int nv, const int *face_start, const int *face_vert, int nf,
                                  double tol, vrPolyhedron **out, char *err, size_t errlen);
void vrPolyhedron_Free(vrPolyhedron *p);

/* The top vertex along d (body frame), climbing from v to a higher
 * neighbour until none is: on a convex polyhedron that vertex is the top.
 * *gap, if not NULL, receives how far it stands above its highest
 * neighbour. */
int vrPolyhedron_Climb(const vrPolyhedron *p, vec3 d, int v, double *gap);

/* the distance of q from the line through a and b */
static inline double vrGeom_DistToLine(vec3 a, vec3 b, vec3 q)
{
    vec3 d = vec3_sub(b, a);
    return vec3_len(vec3_cross(d, vec3_sub(q, a))) / vec3_len(d);
}
/* the diagonal of the bounding box of n points: the size tolerances scale with */
double vrGeom_Size(const vec3 *pts, int n);
/* formats a message into err (when err is not NULL and errlen > 0); returns -1 */
int vrGeom_Fail(char *err, size_t errlen, const char *fmt, ...);

#endif
