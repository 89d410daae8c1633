/* orient.h — the exact orientation of four points (Shewchuk 1997). */
#ifndef VROC_ORIENT_H
#define VROC_ORIENT_H

#include "vec.h"

/* > 0 when p is above the plane of triangle abc (counter-clockwise seen from
 * above), < 0 below, 0 exactly on it; 6 times the volume of abcp, its sign
 * exact */
double vrOrient(vec3 a, vec3 b, vec3 c, vec3 p);

#endif
