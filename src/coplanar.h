/* coplanar.h — the hull's coplanar triangles merged into polygon faces
 * (coplanar.c). */
#ifndef VROC_COPLANAR_H
#define VROC_COPLANAR_H

#include "quickhull.h"

/* Polygon loops: CSR, like the polyhedron's faces (loop f is
 * vert[start[f] .. start[f+1]), point indices, counter-clockwise seen from
 * outside); group[f] is the polygon's, < 0 once dropped */
typedef struct vrLoops { int n, len, cap, capn; int *start; int *vert; int *group; } vrLoops;

/* The polygons of mesh (over pts[0..npts)): triangles whose corners lie
 * within tolabs (metres) of one plane, each loop convex and simple, the
 * corners on fewer than three polygons still in.  Returns 0, -1 (no memory)
 * or VR_HULL_RETRY with a message in err; *out is the caller's to free
 * with vrLoops_Free, whatever the result. */
int vrCoplanar_Merge(const vrHullMesh *mesh, const vec3 *pts, int npts, double tolabs, vrLoops *out, char *err,
                     size_t errlen);
void vrLoops_Free(vrLoops *l);

#endif
