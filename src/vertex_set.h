/* vertex_set.h — small sets of vertex indices (vertex_set.c), and the
 * vertices of a hull above a plane.  The contact floor's (canonical.c,
 * region.c). */
#ifndef VROC_VERTEX_SET_H
#define VROC_VERTEX_SET_H

#include "feature.h"

/* a small set of vertex indices, inline until it outgrows its buffer */
typedef struct vrIntSet { int n, cap; int *v; int buf[32]; } vrIntSet;

void vrIntSet_Init(vrIntSet *s);
void vrIntSet_Free(vrIntSet *s);
/* is x in s (a scan) */
int vrIntSet_Has(const vrIntSet *s, int x);
/* x added at the end: 0, or -1 on no memory */
int vrIntSet_Add(vrIntSet *s, int x);
/* ascending */
void vrIntSet_Sort(vrIntSet *s);
/* Adds the vertices of p with d.v >= floor (body frame) reachable from
 * `seed` through such vertices: on a convex polytope all of them, when the
 * set holds the top vertex.  -1 when out of memory. */
int vrIntSet_Collect(const vrPolyhedron *p, vec3 d, int seed, double floor, vrIntSet *out);

#endif
