/* quickhull.h — the triangulated convex hull of a point set (quickhull.c),
 * what the facet merge (coplanar.c) and the hull (hull.c) start from. */
#ifndef VROC_QUICKHULL_H
#define VROC_QUICKHULL_H

#include <stddef.h>
#include "vec.h"

/* Failures of one hull attempt: -1, refused input (or no memory), is final;
 * VR_HULL_RETRY, a numerical inconsistency, is tried again with close points
 * merged (hull.c). */
#define VR_HULL_RETRY (-2)

/* n triangles over the input points, counter-clockwise seen from outside;
 * nb[i][k] is the triangle across the edge v[i][k] -> v[i][k+1] */
typedef struct vrHullMesh { int n; int (*v)[3]; int (*nb)[3]; } vrHullMesh;

/* The hull of pts[0..n) (n >= 4, finite), points within 1e-3 tolabs of it
 * dropped; refuses points that coincide, are collinear or coplanar within
 * tolabs (metres).  Returns 0, -1 or VR_HULL_RETRY with a message in err;
 * *out is empty unless 0. */
int vrQuickhull(const vec3 *pts, int n, double tolabs, vrHullMesh *out, char *err, size_t errlen);
void vrHullMesh_Free(vrHullMesh *m);

#endif
