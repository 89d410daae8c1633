/* segment.h — closest points of segments (segment.c). */
#ifndef VROC_SEGMENT_H
#define VROC_SEGMENT_H

#include "vec.h"

/* Parameters in [0, 1] of the closest points of segments p0p1 and q0q1
 * (parallel segments: the middle of their overlap) */
void vrSegment_ClosestParams(vec3 p0, vec3 p1, vec3 q0, vec3 q1, double *s, double *t);
/* the parameter in [0, 1] of the point of p0p1 closest to x */
double vrSegment_PointParam(vec3 p0, vec3 p1, vec3 x);

#endif
