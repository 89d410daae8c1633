/* closest_walk.h — the closest-feature walk's state (closest.c), shared
 * with the exhaustive search that ends a walk past its step cap
 * (closest_exhaustive.c): the pair in side 0's frame, the features it is
 * on, and how a point or direction goes from one side's frame into the
 * other's. */
#ifndef VROC_CLOSEST_WALK_H
#define VROC_CLOSEST_WALK_H

#include "closest.h"

/* a step's outcome besides VR_WALK_GO and VR_WALK_DONE: the bodies overlap */
#define VR_WALK_PENETRATING (VR_WALK_DONE + 1)

typedef struct vrWalk {
    const vrPolyhedron *p[2];
    mat33 R;             /* side 1's frame into side 0's: x0 = R x1 + t */
    vec3 t;
    vrFeature f[2];
    double tol;
    double slack2;       /* this step's largest region excess let pass as within tol, squared */
    vec3 c[2];           /* closest points of the final pair, frame 0 */
    double pen_dist;     /* on penetration: <= 0, and where (frame 0) */
    vec3 pen_point;
} vrWalk;

/* x (a point, or with rotate_other a direction) from side i's frame into the other's */
static inline vec3 to_other(const vrWalk *w, int i, vec3 x)
{
    return i ? vec3_add(mat33_mulv(&w->R, x), w->t) : mat33_tmulv(&w->R, vec3_sub(x, w->t));
}
static inline vec3 rotate_other(const vrWalk *w, int i, vec3 v) { return i ? mat33_mulv(&w->R, v) : mat33_tmulv(&w->R, v); }
static inline vec3 in_frame0(const vrWalk *w, int i, vec3 x) { return i == 0 ? x : to_other(w, 1, x); }
static inline vec3 vert_in_other(const vrWalk *w, int i, int v) { return to_other(w, i, w->p[i]->vert[v]); }

static inline int penetrating(vrWalk *w, double dist, vec3 at_frame0)
{
    w->pen_dist = dist;
    w->pen_point = at_frame0;
    return VR_WALK_PENETRATING;
}

#endif
