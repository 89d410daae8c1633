/* shape.c — what collides (SPEC 2): the support point of a posed shape. */
#include "shape.h"

vec3 vrShape_Support(const vrShape *s, const vrPose *p, vec3 dir)
{
    vec3 d;
    int i, best = 0;
    double m;
    if (s->kind == VR_SHAPE_SPHERE) return vec3_madd(p->p, s->radius, vec3_normalize(dir));
    d = mat33_tmulv(&p->R, dir);     /* in the body frame: one rotation, not one per vertex */
    m = vec3_dot(d, s->poly->vert[0]);
    for (i = 1; i < s->poly->nv; i++) {
        double h = vec3_dot(d, s->poly->vert[i]);
        if (h > m) {
            m = h;
            best = i;
        }
    }
    return vrPose_apply(p, s->poly->vert[best]);
}
