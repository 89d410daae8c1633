/* sphere.h — what a true sphere's centre sees of the other shape (sphere.c,
 * closed forms; thesis 3.2.1). */
#ifndef VROC_SPHERE_H
#define VROC_SPHERE_H

#include "closest.h"
#include "shape.h"

/* What a sphere's centre c sees of the other shape: its closest point q, the
 * unit direction from the shape toward c, and c's signed distance (negative
 * inside). */
typedef struct vrNear { vec3 q, dir; double dist; } vrNear;

/* a sphere of centre `centre` and radius r */
vrNear vrNear_Sphere(vec3 centre, double r, vec3 c);
/* a box shape at pose: clamp into the box; inside, the nearest face */
vrNear vrNear_Box(const vrShape *box, const vrPose *pose, vec3 c);
/* polyhedron p at pose: the walk to c (cache: its feature), steps taken;
 * -1 when out of memory */
int vrNear_Poly(const vrPolyhedron *p, const vrPose *pose, vec3 c, vrWalkCache *cache, int *steps, vrNear *nr);

#endif
