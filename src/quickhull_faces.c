/* quickhull_faces.c — the quickhull's faces (quickhull.c): a new
 * triangle with its normal and height filter, and the conflict lists
 * that keep each outside point above one face.
 *
 *   set_plane, vrQuickhull_NewFace   a triangle, its normal and the sums its filter bounds
 *   add_conflict                     a point onto a face's list (the farthest kept)
 *   over_triangle                    whether a point lies over a face's triangle
 *   vrQuickhull_Assign               a point to a face of a step, or dropped
 */
#include <math.h>

#include "grow.h"
#include "quickhull_faces.h"

static void set_plane(Face *f, vec3 a, vec3 b, vec3 c)
{
    vec3 u = vec3_sub(b, a), v = vec3_sub(c, a);
    f->n = vec3_cross(u, v);
    f->nabs = vec3_make(fabs(u.y * v.z) + fabs(u.z * v.y), fabs(u.z * v.x) + fabs(u.x * v.z),
                        fabs(u.x * v.y) + fabs(u.y * v.x));
}

int vrQuickhull_NewFace(Hull *h, int a, int b, int c)
{
    Face *f;
    int id;
    if (h->freeface.n > 0) {
        id = h->freeface.a[--h->freeface.n];
    } else {
        if (vrGrow((void **)&h->face, &h->capface, h->nface + 1, sizeof *h->face) != 0) {
            h->oom = 1;
            return -1;
        }
        id = h->nface++;
    }
    f = &h->face[id];
    f->v[0] = a;
    f->v[1] = b;
    f->v[2] = c;
    f->nb[0] = f->nb[1] = f->nb[2] = -1;
    f->head = f->far = -1;
    f->fardist = 0;
    set_plane(f, h->pts[a], h->pts[b], h->pts[c]);
    f->minout = h->drop * vec3_len(f->n);
    f->stamp = 0;
    f->state = FACE_ALIVE;
    return id;
}

static void add_conflict(Hull *h, int f, int pt, double d)
{
    Face *F = &h->face[f];
    h->next[pt] = F->head;
    F->head = pt;
    if (F->far < 0 || d > F->fardist) {
        F->far = pt;
        F->fardist = d;
    }
}

/* does pt, seen along the normal of face F, fall on its triangle?  A
 * sliver's normal is mostly rounding (its products cancel): no answer */
static int over_triangle(const Hull *h, const Face *F, int pt)
{
    vec3 p = h->pts[pt];
    int i;
    if (vec3_maxabs(F->n) <= 1e-6 * vec3_maxabs(F->nabs)) return 0;
    for (i = 0; i < 3; i++) {
        vec3 a = h->pts[F->v[i]], b = h->pts[F->v[i == 2 ? 0 : i + 1]];
        if (vec3_dot(vec3_cross(vec3_sub(b, a), vec3_sub(p, a)), F->n) < 0) return 0;
    }
    return 1;
}

/* the conflict lists (quickhull_faces.h): drop or keep, the reasons below */
void vrQuickhull_Assign(Hull *h, int pt, const int *faces, int n, int *hint)
{
    int k, above = -1;
    double dabove = 0;
    for (k = 0; k < n; k++) {
        int at = *hint + k < n ? *hint + k : *hint + k - n, f = faces[at];
        const Face *F = &h->face[f];
        double eb, d = height(h, F, pt, &eb);
        if (d - F->minout > eb) {
            add_conflict(h, f, pt, d);
            *hint = at;
            return;
        }
        if (fabs(d) <= F->minout + eb && over_triangle(h, F, pt)) return;
        if (d > eb && above < 0) {
            above = f;
            dabove = d;
        }
    }
    for (k = 0; k < n && above < 0; k++) { /* the sign too close to call: exactly */
        double eb, d = height(h, &h->face[faces[k]], pt, &eb);
        if (fabs(d) <= eb && face_orient(h, faces[k], pt) > 0) above = faces[k];
    }
    if (above >= 0) add_conflict(h, above, pt, dabove);
}
