/* hand_filter.c — the 1€ filter on the hand's samples (see hand_filter.h). */
#include "hand_filter.h"
#include "track.h"

#define D_CUTOFF 1.0   /* Hz: the speed's own smoothing (the paper's default) */
#define TWO_PI 6.28318530717958647692

/* the paper's smoothing factor for a cutoff fc over a time te */
static double alpha(double te, double fc) { return 1.0 / (1.0 + 1.0 / (TWO_PI * fc * te)); }

static vec3 position(const vrTrackerSample *s) { return vec3_make(s->position[0], s->position[1], s->position[2]); }

static quat orientation(const vrTrackerSample *s)
{
    return quat_make(s->orientation[0], s->orientation[1], s->orientation[2], s->orientation[3]);
}

/* the turn of a slerp from a to b by u (vrTrack_Turn: the short way) */
static quat slerp(quat a, quat b, double u)
{
    return quat_normalize(quat_mul(quat_from_rotvec(vec3_scale(vrTrack_Turn(a, b), u)), a));
}

vrHandFiltered vrHandFilter_Next(const vrHandFilter *f, const vrTrackerSample *s, double min_cutoff, double beta)
{
    vrHandFiltered r;
    double te, a;
    r.t = s->t;
    r.x = position(s);
    r.q = quat_normalize(orientation(s));
    r.dx = vec3_zero();
    te = f->n ? s->t - f->last.t : 0;
    if (!(te > 0)) {                  /* the first sample, or one at the same time: taken as it is */
        if (f->n) r.dx = f->last.dx;
        return r;
    }
    a = alpha(te, D_CUTOFF);
    r.dx = vec3_add(vec3_scale(vec3_scale(vec3_sub(r.x, f->last.x), 1 / te), a), vec3_scale(f->last.dx, 1 - a));
    a = alpha(te, min_cutoff + beta * vec3_len(r.dx));
    r.x = vec3_add(vec3_scale(r.x, a), vec3_scale(f->last.x, 1 - a));
    r.q = slerp(f->last.q, r.q, a);
    return r;
}

void vrHandFilter_Take(vrHandFilter *f, const vrTrackerSample *s, double min_cutoff, double beta)
{
    vrHandFiltered next = vrHandFilter_Next(f, s, min_cutoff, beta);
    f->prev = f->last;
    f->last = next;
    if (f->n < 2) f->n++;   /* 2: prev and last are both samples */
}

void vrHandFilter_Between(const vrHandFiltered *a, const vrHandFiltered *b, double t, vrTrackerSample *out)
{
    double u = b->t > a->t ? (t - a->t) / (b->t - a->t) : 1;
    vec3 x = vec3_lerp(a->x, b->x, u);
    quat q = slerp(a->q, b->q, u);
    out->t = t;
    out->position[0] = x.x, out->position[1] = x.y, out->position[2] = x.z;
    out->orientation[0] = q.w, out->orientation[1] = q.x, out->orientation[2] = q.y, out->orientation[3] = q.z;
}
