/* shape.c — a shape's support point (shape.h): the farthest vertex along a
 * direction, the first of equals, by a scan of a few vertices or a climb
 * over many (a superquadric of 300 x 300 points scanned its 90,000 at
 * every call of libccd's MPR: half of a frame of such bodies meeting). */
#include "shape.h"
#include "polyhedron.h"
#include "vertex_set.h"

#define SCAN_MOST 64    /* vertices scanned outright; a larger hull is climbed */

/* the scan's answer: the highest along d (body frame), the first of equals */
static int scanned_top(const vrPolyhedron *p, vec3 d)
{
    double m = vec3_dot(d, p->vert[0]);
    int i, best = 0;
    for (i = 1; i < p->nv; i++) {
        double h = vec3_dot(d, p->vert[i]);
        if (h > m) {
            m = h;
            best = i;
        }
    }
    return best;
}

/* The scan's answer by a climb from `start`.  A climb ends on a vertex no
 * neighbour beats; the vertices that rounding could rank with it or above
 * it lie within `slack` of it, and those above a plane of a convex
 * polyhedron are joined by its edges (vrIntSet_Collect meets every one):
 * of those, the highest, the first of equals, as the scan would pick.  A
 * top that stands clear of its neighbours is the answer at once. */
static int climbed_top(const vrPolyhedron *p, vec3 d, int start)
{
    vrIntSet near;
    double gap, h, slack, hb;
    int v = vrPolyhedron_Climb(p, d, start, &gap), i, best = v;
    h = hb = vec3_dot(d, p->vert[v]);
    slack = 1e-12 * vec3_len(d) * vec3_len(p->vert[v]);
    if (gap > slack) return v;
    vrIntSet_Init(&near);
    if (vrIntSet_Collect(p, d, v, h - slack, &near) != 0) {   /* no memory */
        vrIntSet_Free(&near);
        return scanned_top(p, d);
    }
    for (i = 0; i < near.n; i++) {
        double hw = vec3_dot(d, p->vert[near.v[i]]);
        if (hw > hb || (hw == hb && near.v[i] < best)) hb = hw, best = near.v[i];
    }
    vrIntSet_Free(&near);
    return best;
}

int vrShape_TopVertex(const vrPolyhedron *p, vec3 d, int start)
{
    if (p->nv <= SCAN_MOST) return scanned_top(p, d);
    return climbed_top(p, d, start >= 0 && start < p->nv ? start : 0);
}

vec3 vrShape_SupportFrom(const vrShape *s, const vrPose *p, vec3 dir, int *hint)
{
    int v;
    if (s->kind == VR_SHAPE_SPHERE) return vec3_madd(p->p, s->radius, vec3_normalize(dir));
    /* in the body frame: one rotation, not one per vertex */
    v = vrShape_TopVertex(s->poly, mat33_tmulv(&p->R, dir), hint ? *hint : 0);
    if (hint && s->poly->nv > SCAN_MOST) *hint = v;
    return vrPose_apply(p, s->poly->vert[v]);
}

vec3 vrShape_Support(const vrShape *s, const vrPose *p, vec3 dir) { return vrShape_SupportFrom(s, p, dir, NULL); }
