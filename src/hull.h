/* hull.h — the convex hull of a point set, as a polyhedron (hull.c). */
#ifndef VROC_HULL_H
#define VROC_HULL_H

#include "polyhedron.h"

/* convex hull of points (relative tolerance 1e-9 for coplanarity); refuses
 * fewer than 4 non-coplanar points */
int vrPolyhedron_Hull(const vec3 *pts, int n, vrPolyhedron **out, char *err, size_t errlen);
/* vrPolyhedron_Hull with its relative tolerance tol.  When src is not NULL,
 * *src receives a malloc'ed array of nv entries: the index in pts of each
 * vertex of the result (the caller frees it). */
int vrPolyhedron_HullTol(const vec3 *pts, int n, double tol, int **src, vrPolyhedron **out, char *err,
                         size_t errlen);

#endif
