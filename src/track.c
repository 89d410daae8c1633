/* track.c — one tracker's samples and the motion between them (SPEC 8).
 *
 *   segment        the sample at or before t (binary search)
 *   vrTrack_Turn   the rotation vector taking one orientation to the next
 *   vrTrack_At     the interpolated pose: lerp and slerp
 *   vrTrack_Velocity   the motion's velocity on a segment (the throw, SPEC 8)
 *
 * Slerp is written as a constant turn about one world axis from the
 * earlier orientation, q(u) = exp(u r / 2) q0, so that the angular velocity
 * it makes is exactly r / dt on the whole segment: a hand turning steadily
 * throws with the spin its samples say.
 */
#include <stdlib.h>
#include <string.h>
#include "track.h"
#include "vec.h"

int vrTrack_Push(vrTrack *tr, const vrTrackerSample *s)
{
    if (tr->n > 0 && s->t < tr->s[tr->n - 1].t) return -2;
    if (tr->n == tr->cap) {
        int cap = tr->cap ? 2 * tr->cap : 16;
        vrTrackerSample *m = realloc(tr->s, (size_t)cap * sizeof *m);
        if (!m) return -1;
        tr->s = m;
        tr->cap = cap;
    }
    tr->s[tr->n++] = *s;
    return 0;
}

/* the last sample at or before t, or -1 when t is before them all */
static int segment(const vrTrack *tr, double t)
{
    int lo = 0, hi = tr->n - 1;
    if (tr->n == 0 || t < tr->s[0].t) return -1;
    while (lo < hi) {
        int mid = lo + (hi - lo + 1) / 2;
        if (tr->s[mid].t <= t) lo = mid;
        else hi = mid - 1;
    }
    return lo;
}

void vrTrack_Forget(vrTrack *tr, double t)
{
    int k = segment(tr, t);
    if (k <= 0) return;
    memmove(tr->s, tr->s + k, (size_t)(tr->n - k) * sizeof *tr->s);
    tr->n -= k;
}

static quat sample_quat(const vrTrackerSample *s)
{
    return quat_make(s->orientation[0], s->orientation[1], s->orientation[2], s->orientation[3]);
}

vec3 vrTrack_Turn(quat q0, quat q1)
{
    quat d = quat_mul(q1, quat_conj(q0));
    vec3 v;
    double s;
    if (d.w < 0) d = quat_make(-d.w, -d.x, -d.y, -d.z);
    v = vec3_make(d.x, d.y, d.z);
    s = vec3_len(v);
    return s > 0 ? vec3_scale(v, 2 * atan2(s, d.w) / s) : vec3_zero();
}

static void set_pose(vrTrackerSample *out, vec3 p, quat q)
{
    q = quat_normalize(q);
    out->position[0] = p.x, out->position[1] = p.y, out->position[2] = p.z;
    out->orientation[0] = q.w, out->orientation[1] = q.x, out->orientation[2] = q.y, out->orientation[3] = q.z;
}

static vec3 sample_pos(const vrTrackerSample *s) { return vec3_make(s->position[0], s->position[1], s->position[2]); }

int vrTrack_At(const vrTrack *tr, double t, vrTrackerSample *out)
{
    int k = segment(tr, t);
    const vrTrackerSample *a, *b;
    double u;
    if (tr->n == 0) return -1;
    if (k < 0) k = 0;
    a = &tr->s[k];
    *out = *a;
    out->t = t;
    if (k + 1 >= tr->n || !(t > a->t)) return 0;
    b = &tr->s[k + 1];
    u = (t - a->t) / (b->t - a->t);
    set_pose(out, vec3_lerp(sample_pos(a), sample_pos(b), u),
             quat_mul(quat_from_rotvec(vec3_scale(vrTrack_Turn(sample_quat(a), sample_quat(b)), u)), sample_quat(a)));
    return 0;
}

int vrTrack_Velocity(const vrTrack *tr, double t, double v[3], double w[3])
{
    int k = segment(tr, t);
    vec3 dv = vec3_zero(), dw = vec3_zero();
    if (tr->n == 0) return -1;
    if (k >= 0 && k + 1 < tr->n && tr->s[k + 1].t > tr->s[k].t) {
        const vrTrackerSample *a = &tr->s[k], *b = &tr->s[k + 1];
        double dt = b->t - a->t;
        dv = vec3_scale(vec3_sub(sample_pos(b), sample_pos(a)), 1 / dt);
        dw = vec3_scale(vrTrack_Turn(sample_quat(a), sample_quat(b)), 1 / dt);
    }
    v[0] = dv.x, v[1] = dv.y, v[2] = dv.z;
    w[0] = dw.x, w[1] = dw.y, w[2] = dw.z;
    return 0;
}

void vrTrack_Clear(vrTrack *tr) { tr->n = 0; }

void vrTrack_Free(vrTrack *tr)
{
    free(tr->s);
    memset(tr, 0, sizeof *tr);
}
