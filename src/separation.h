/* separation.h — how far apart two posed polyhedra are along a direction,
 * and the direction a walk's last features say they separate along
 * (separation.c), from which canonical.c builds the support sets. */
#ifndef VROC_SEPARATION_H
#define VROC_SEPARATION_H

#include "canonical.h"

/* How far apart a (from vertex va) and b (from vb), or a and the point c
 * when b is NULL, are along world direction u: the gap between their
 * support planes, by climbing the vertex graphs to the scan's answers
 * (vrShape_TopVertex): the same bits whichever vertices the climbs start
 * at, where tops tie along a face's normal. */
typedef struct vrGap { const vrPosed *a, *b; vec3 c; int va, vb; } vrGap;

double vrGap_Along(const vrGap *g, vec3 u);
/* The same by plain climbs (the top where a climb stops, a rounding from
 * the scan's among tied tops), with g's vertices moved to the tops they
 * reached: the next direction nearby starts there (a fine superquadric's
 * climbs from the walk's vertices to each of its faces' normals are long) */
double vrGap_AlongFrom(vrGap *g, vec3 u);
/* The direction of separation at the walk's final features fa, fb (fb
 * unused for a point), its closest points ca, cb and distance dw. */
vec3 vrGap_WalkDirection(const vrGap *g, vrFeature fa, vrFeature fb, vec3 ca, vec3 cb, double dw);

#endif
