/* balance.c — whether a body lying on its supports is balanced on them
 * (SPEC 7's rest; man vroc, REST).
 *
 * The rest test (rest.c) looks at motion: a body still over two frames
 * rests.  A body that rocks up onto an edge and slows is still at its
 * turning point too, and was put to rest there, leaning where it would fall
 * back (a domino spun onto its edge rested 3.4 degrees up, inside its
 * 5.7-degree tipping angle).  Statics say when a body may rest.  One that
 * only lies on things (each of its contacts pushes it against the force,
 * all along one normal) is balanced when the force's line through its
 * centre of mass meets its support, the hull of its contact points, seen
 * along the force: the contact forces balancing the force add up to one
 * force on that line, and forces along one normal at those points add up
 * to a force through their hull only (on a slope the friction that holds
 * the body tilts them alike and moves nothing).  Only the points within
 * SUPPORT_GAP of g_c bear it (of its nearest, when that is higher): the
 * contact solve holds a point at g_c or nearer, and lets one farther off
 * close its gap.  A touch's region reaches 2 g_c, and a domino 3.4 degrees
 * up has 34 mm of its 40 mm face within 2 mm of the floor, its centre 8 mm
 * off its edge; and a box lying at rest may have a corner 0.2 mm nearer
 * than g_c, left so by the solve, and its other corners at g_c.  The band
 * lets a domino (a 4 cm foot) rest up to 0.03 degrees off level, inside the rest
 * test's 1e-3 rad.  A body touching
 * along several normals (in a pile, leaning on a wall, in a V) is not
 * judged: its rest is its motion's alone.  Every touch counts, those
 * leaving too: a pile's contacts tap its bodies apart at mm/s, and a body
 * seen through its island's contacts alone lay on one of them.
 *   Judged               what one pass over the touches finds of each body
 *   judge                the touches' pass
 *   inside_support       one judged body's test, by region.c's support containment
 *   vrBalance_Mark       (balance.h)
 */
#include <stdlib.h>
#include <math.h>
#include "balance.h"
#include "region.h"
#include "config.h"

#define SUPPORT_GAP 2e-5      /* m: points this far beyond g_c (or the nearest) bear nothing yet */
#define BALANCE_SLACK 1e-4    /* m: a centre this near its support's hull is on it (rounding, a region's
                               * points within SUPPORT_GAP) */
#define SUPPORT_ALIGN 1e-3    /* 1 - cos: normals this close are one (2.6 degrees) */
#define SUPPORT_UP 0.1        /* a support's normal is within 84 degrees of up (a wall holds nothing up) */

typedef struct Judged {
    int id;                   /* the body's object id */
    int contacts;             /* its touches so far; -1: not judged (a touch not a support) */
    int last;                 /* its last touch's side (2 k + e: touch k's a or b), -1: none */
    int points;               /* its touches' points in all */
    vec3 n;                   /* its first touch's normal, into the body */
    double nearest;           /* its touches' least gap */
} Judged;

/* Each moving body of the touches gets a slot (isl_slot, by id) and
 * its Judged: supports along one normal, or not judged.  Side 2 k + e of
 * touch k (its a, its b) links to the same body's side before it (prev),
 * so that a judged body's touches are found without a search.  The
 * number of bodies. */
static int judge(vrWorld *w, const vrTouch *t, int nt, vec3 up, Judged *j, int *prev)
{
    int k, e, p, nb = 0;
    for (k = 0; k < nt; k++)
        for (e = 0; e < 2; e++) {
            int id = e ? t[k].b : t[k].a;
            vec3 n = e ? t[k].n : vec3_neg(t[k].n);   /* from a toward b: into b */
            Judged *x;
            prev[2 * k + e] = -1;
            if (vrBody_Immovable(&w->table.obj[id]->body)) continue;
            if (w->isl_slot[id] < 0) {
                x = &j[w->isl_slot[id] = nb++];
                x->id = id, x->contacts = x->points = 0, x->last = -1;
            }
            x = &j[w->isl_slot[id]];
            prev[2 * k + e] = x->last;
            x->last = 2 * k + e;
            if (x->contacts < 0) continue;
            if (vec3_dot(n, up) < SUPPORT_UP || (x->contacts > 0 && vec3_dot(n, x->n) < 1 - SUPPORT_ALIGN)) {
                x->contacts = -1;
                continue;
            }
            if (x->contacts++ == 0) x->n = n, x->nearest = INFINITY;
            x->points += t[k].npoints;
            for (p = 0; p < t[k].npoints; p++) x->nearest = fmin(x->nearest, t[k].gap[p]);
        }
    return nb;
}

/* how far the judged body's centre c lies inside its support (its
 * touches' points near g_c), seen along the force up: SPEC 3.1's
 * containment of a support (region.h); +INFINITY with no points (nothing
 * to judge), -INFINITY when out of memory */
static double inside_support(const Judged *x, vec3 c, const vrTouch *t, const int *prev, double gc, vec3 up, vec3 *pt)
{
    double bears = fmax(x->nearest, gc) + SUPPORT_GAP;
    int side, p, m = 0;
    for (side = x->last; side >= 0; side = prev[side]) {
        const vrTouch *k = &t[side / 2];
        for (p = 0; p < k->npoints; p++)
            if (k->gap[p] <= bears) pt[m++] = k->point[p];
    }
    return m == 0 ? INFINITY : vrRegion_Margin(pt, m, up, c);
}

int vrBalance_Mark(vrWorld *w, double t)
{
    const vrTouch *touch = w->touches.t;
    int nt = w->touches.n, i, nb, most = 0, rc = 0;
    vrParams par = vrSettings_Params(&w->s);
    vec3 accel = par.flight.accel, up, *pt;
    double gc = vrParams_Gap(&par);
    Judged *j;
    int *prev;
    if (nt == 0 || vec3_len2(accel) == 0) return 0;   /* no force: nothing tips (flags 0 since the frame began) */
    j = malloc(2 * (size_t)nt * sizeof *j);
    prev = malloc(2 * (size_t)nt * sizeof *prev);
    if (!j || !prev) {
        free(j);
        free(prev);
        return -1;
    }
    up = vec3_normalize(vec3_neg(accel));
    nb = judge(w, touch, nt, up, j, prev);
    for (i = 0; i < nb; i++) {
        w->isl_slot[j[i].id] = -1;    /* as it was: -1 everywhere */
        if (j[i].contacts > 0 && j[i].points > most) most = j[i].points;
    }
    if (!(pt = malloc(((size_t)most + 1) * sizeof *pt))) rc = -1;
    for (i = 0; i < nb && rc == 0; i++) {
        vrObject *o = w->table.obj[j[i].id];
        vrPose pose;
        double inside;
        o->tipping = 0;
        if (j[i].contacts <= 0) continue;
        vrBody_Pose(&o->body, t, &pose);
        inside = inside_support(&j[i], pose.p, touch, prev, gc, up, pt);
        if (inside == -INFINITY) rc = -1;
        o->tipping = inside < -BALANCE_SLACK;
    }
    free(j);
    free(prev);
    free(pt);
    return rc;
}
