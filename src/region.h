/* region.h — the contact region of a pair (SPEC 2) and containment in such
 * regions (SPEC 3.1), region.c. */
#ifndef VROC_REGION_H
#define VROC_REGION_H

#include "vec.h"

/* at most this many points in a contact region */
#define VR_REGION_MAX 64

/* Is q inside the convex hull of pts (n of them) seen along nrm, within
 * tol?  (SPEC 3.1: a support's centre of mass over its contact region.) */
int vrRegion_Contains(const vec3 *pts, int n, vec3 nrm, vec3 q, double tol);
/* How far q lies inside that hull (negative: outside by that much; a
 * point or segment hull gives minus q's distance to it; -INFINITY when out
 * of memory).  Contains is Margin >= -tol. */
double vrRegion_Margin(const vec3 *pts, int n, vec3 nrm, vec3 q);

/* The region of the canonical pair c of a and b (canonical.h) within d:
 * at most VR_REGION_MAX points on the contact plane into point, each
 * one's gap along n between the surfaces into gap (a corner that is a
 * vertex of either body: that vertex's distance from the other's support
 * plane; a corner where the hulls' edges cross: the canonical distance,
 * the least), their number into *npoints; -1 when out of memory. */
struct vrPosed;
struct vrCanon;
int vrRegion_Points(const struct vrPosed *a, const struct vrPosed *b, const struct vrCanon *c, double d, vec3 *point,
                    double *gap, int *npoints);

#endif
