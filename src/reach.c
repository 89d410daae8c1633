/* reach.c — the largest reach of the free bodies from a max-tree of
 * bounds (see reach.h). */
#include <stdlib.h>
#include "reach.h"
#include "grow.h"
#include "schedule.h"

void vrReach_Init(vrReach *r)
{
    r->bound = NULL;
    r->leaves = r->cap = r->n = r->valid = 0;
    r->T = NAN;
}

void vrReach_Free(vrReach *r)
{
    free(r->bound);
    vrReach_Init(r);
}

/* b's reach at any span start from t to T is at most this; the relative
 * margin covers the rounding of the exact reach where the two are equal */
static double bound_of(const vrBody *b, double t, double T, const vrFlight *f)
{
    vec3 v;
    double speed, accel;
    if (!b || !vrBody_IsFree(b)) return -INFINITY;
    accel = vr_max(vec3_len(f->accel), vec3_len(b->m.a));
    vrBody_Velocity(b, t, &v);
    speed = vec3_len(v) + accel * (T - t);
    if (!b->m.over_cap) speed = vr_min(f->max_linear, speed);   /* a throw flies uncapped (motion.c) */
    return (speed + vrSchedule_SpinReach(b)) * (1 + 1e-9) + 1e-12;
}

static void lift(vrReach *r, int k)
{
    for (k /= 2; k >= 1; k /= 2) r->bound[k] = vr_max(r->bound[2 * k], r->bound[2 * k + 1]);
}

void vrReach_Frame(vrReach *r, vrBody *const *bodies, int n, double t0, double T, const vrFlight *f)
{
    int leaves = 1, k;
    while (leaves < n) leaves *= 2;
    r->valid = 0;
    if (vrGrow((void **)&r->bound, &r->cap, 2 * leaves, sizeof *r->bound) != 0) return;
    r->leaves = leaves;
    r->n = n;
    r->T = T;
    for (k = 0; k < leaves; k++) r->bound[leaves + k] = k < n ? bound_of(bodies[k], t0, T, f) : -INFINITY;
    for (k = leaves - 1; k >= 1; k--) r->bound[k] = vr_max(r->bound[2 * k], r->bound[2 * k + 1]);
    r->valid = 1;
}

void vrReach_Changed(vrReach *r, vrBody *const *bodies, int i, double t, const vrFlight *f)
{
    if (!r->valid || i < 0 || i >= r->n) return;
    r->bound[r->leaves + i] = bound_of(bodies[i], t, r->T, f);
    lift(r, r->leaves + i);
}

double vrReach_Fastest(const vrReach *r, vrBody *const *bodies, double ts, const vrFlight *f)
{
    int stack[64], top = 0;
    double best = 0;
    stack[top++] = 1;
    while (top > 0) {
        int k = stack[--top];
        if (!(r->bound[k] > best)) continue;       /* nothing below can beat it */
        if (k >= r->leaves) {
            best = vr_max(best, vrSchedule_Reach(bodies[k - r->leaves], ts, r->T, f));
        } else {                                   /* the more promising child first */
            int hi = r->bound[2 * k] >= r->bound[2 * k + 1] ? 2 * k : 2 * k + 1;
            stack[top++] = hi ^ 1;
            stack[top++] = hi;
        }
    }
    return best;
}
