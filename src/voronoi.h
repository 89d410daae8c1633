/* voronoi.h — the Voronoi regions of a polyhedron's features (voronoi.c,
 * V-Clip sec. 3).  Points are in the polyhedron's body frame. */
#ifndef VROC_VORONOI_H
#define VROC_VORONOI_H

#include "feature.h"

/* The neighbour beyond the region plane of f that x violates most, by more
 * than tol metres: 1 and *nbr.  0 when x lies in f's region (within tol),
 * and then *slack2 (if not NULL) is raised to the square of the largest
 * excess let pass. */
int vrVoronoi_Violation(const vrPolyhedron *p, vrFeature f, vec3 x, double tol, vrFeature *nbr, double *slack2);
/* The part [lo, hi] of segment t..h inside face f's prism (the planes of
 * its region through its edges); 0 when the segment misses it. */
int vrVoronoi_ClipToFace(const vrPolyhedron *p, int f, vec3 t, vec3 h, double *lo, double *hi);
/* is x inside face f's prism? */
int vrVoronoi_InPrism(const vrPolyhedron *p, int f, vec3 x);
/* the face whose plane x lies farthest above (the nearest one when x is
 * inside), and that height */
int vrVoronoi_HighestFace(const vrPolyhedron *p, vec3 x, double *height);
/* the closest point of feature f to x, for x in f's region */
vec3 vrVoronoi_ClosestOnFeature(const vrPolyhedron *p, vrFeature f, vec3 x);

#endif
