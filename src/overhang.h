/* overhang.h — a support feature that reaches past a face, measured over
 * the face only (overhang.c; internal to canonical.c and its tests). */
#ifndef VROC_OVERHANG_H
#define VROC_OVERHANG_H

#include "canonical.h"

/* Face f of fb (world plane n.x = h, n its outward normal) against the
 * support feature s of `other`, an edge or a face within 1e-9 m of
 * parallel to it: when a vertex of s lies beyond the face (seen along n),
 * the part of s over the face is measured instead of all of s.  Returns 1
 * with *low the lowest height (n.x) of that part and *at its middle (a
 * point of s); 0 when s is a vertex, lies over the face within
 * VR_REGION_SLACK, or has no part over it (then all of s is measured, as
 * before); -1 when out of memory. */
int vrOverhang_Lowest(const vrPosed *fb, int f, vec3 n, const vrPosed *other, const vrSupportFeature *s, double *low,
                      vec3 *at);

#endif
