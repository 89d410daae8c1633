/* rest.c — the rest state (thesis 3.3.3, generalised as SPEC 3.5).
 *
 * At a frame end a supported body that moved less than 1e-4 m and turned
 * less than 1e-3 rad over the frame, and that no impulse hit, rests: no
 * force, no motion, its pose frozen as it is (never snapped), its pairs with
 * its supports unscheduled.  Its supports must themselves be frozen (static
 * or resting): a frictionless body does not ride on a sliding one.  A
 * resting body wakes when a response involves it or a support changes;
 * waking anything wakes what rests on it.
 *
 *   qualifies     may this body rest now?
 *   wanted        the bodies several contacts together may carry
 *   carried       is the centre of mass over all their regions together?
 *   settle_joint  the normal relative velocity goes, momentum kept
 *   decide        one body's candidates: support by them together begins or ends
 */
#include <stdlib.h>
#include <string.h>
#include "config.h"
#include "rest.h"

#define REST_DISPLACEMENT 1e-4   /* m per frame */
#define CONTAIN_TOL 1e-9         /* m */
#define REST_ROTATION 1e-3       /* rad per frame */

static const vrBodyState *in_update(const vrUpdate *up, int id)
{
    int i;
    for (i = 0; i < up->n; i++)
        if (up->body[i].id == id) return &up->body[i];
    return NULL;
}

static int rests_on(const vrBody *b, int partner)
{
    int i;
    for (i = 0; i < b->nsupport; i++)
        if (b->support[i].partner == partner) return 1;
    return 0;
}

int vrRest_WakeDependents(vrWorld *w, vrUpdate *up, double t)
{
    int k, i;
    if (w->may_rest == 0) return 0;     /* nothing rests: no look at every object */
    for (k = 0; k < up->n; k++) {
        int id = up->body[k].id;
        for (i = 0; i < w->table.n; i++) {
            vrObject *x = w->table.obj[i];
            vrBodyState *st;
            if (!x || !x->live || !x->body.resting || !rests_on(&x->body, id) || in_update(up, i)) continue;
            st = vrUpdate_Body(up, &x->body, t);
            if (!st) return -1;
            st->resting = 0;
        }
    }
    return 0;
}

/* frozen now, or about to rest in this same update */
static int frozen_support(const vrWorld *w, const vrUpdate *up, int id)
{
    const vrObject *o = w->table.obj[id];
    const vrBodyState *st = in_update(up, id);
    return o && (o->body.is_static || o->body.resting || (st && st->resting));
}

static int qualifies(vrWorld *w, const vrUpdate *up, vrObject *o)
{
    vrBody *b = &o->body;
    vrPose p;
    int i;
    if (!o->live || b->is_static || b->resting || b->hit || b->nsupport == 0 || !o->have_frame_pose) return 0;
    if (in_update(up, b->id)) return 0;
    for (i = 0; i < b->nsupport; i++)
        if (!frozen_support(w, up, b->support[i].partner)) return 0;
    vrBody_Pose(b, w->t, &p);
    return vec3_dist(p.p, o->frame_pose.p) < REST_DISPLACEMENT
        && quat_angle_between(o->frame_pose.q, p.q) < REST_ROTATION;
}

int vrRest_FrameEnd(vrWorld *w, vrUpdate *up)
{
    int more = 1, i;
    while (more) {              /* a stack comes to rest from the bottom up */
        more = 0;
        for (i = 0; i < w->table.n; i++) {
            vrObject *o = w->table.obj[i];
            vrBodyState *st;
            if (!o || !qualifies(w, up, o)) continue;
            st = vrUpdate_Body(up, &o->body, w->t);
            if (!st) return -1;
            st->resting = 1;
            w->may_rest = w->table.n;      /* counted again once applied */
            more = 1;
        }
    }
    return 0;
}

void vrRest_RememberFramePoses(vrWorld *w)
{
    int i;
    w->may_rest = 0;
    for (i = 0; i < w->table.n; i++) {
        vrObject *o = w->table.obj[i];
        if (!o || !o->live || o->body.is_static) continue;
        w->may_rest += o->body.resting;
        vrBody_Pose(&o->body, w->t, &o->frame_pose);
        o->have_frame_pose = 1;
        o->body.hit = 0;
    }
}

/* ---- several supports at once ------------------------------------------------------ */

static int joint_supports(const vrBody *b)
{
    int i, k = 0;
    for (i = 0; i < b->nsupport; i++) k += b->support[i].joint;
    return k;
}

/* bodies no single contact carries that an impulse hit this frame (they may
 * be lying across several supports), and bodies carried by several
 * contacts together (are they still?) */
static unsigned char *wanted(const vrWorld *w, int *count)
{
    unsigned char *want = calloc((size_t)w->table.n + 1, 1);
    int i;
    *count = 0;
    for (i = 0; want && i < w->table.n; i++) {
        const vrBody *b;
        if (!w->table.obj[i] || !w->table.obj[i]->live) continue;
        b = &w->table.obj[i]->body;
        if (b->is_static || b->resting) continue;
        if (!((b->nsupport == 0 && b->hit) || joint_supports(b) > 0)) continue;
        want[i] = 1;
        (*count)++;
    }
    return want;
}

static int by_body(const void *x, const void *y)
{
    const vrCandidate *a = x, *b = y;
    if (a->body != b->body) return a->body < b->body ? -1 : 1;
    return a->partner < b->partner ? -1 : a->partner > b->partner;
}

/* the centre of mass over all the contacts' regions together, seen along
 * the force */
static int carried(vrWorld *w, const vrCandidate *c, int k, vec3 g, double T)
{
    vec3 *pts, com;
    vrPose p;
    int i, n = 0, inside;
    for (i = 0; i < k; i++) n += c[i].npoints;
    pts = malloc((size_t)n * sizeof *pts);
    if (!pts) return 0;
    for (i = 0, n = 0; i < k; i++) {
        memcpy(pts + n, c[i].point, (size_t)c[i].npoints * sizeof *pts);
        n += c[i].npoints;
    }
    vrBody_Pose(&w->table.obj[c[0].body]->body, T, &p);
    com = p.p;
    inside = vrRegion_Contains(pts, n, vec3_normalize(g), com, CONTAIN_TOL);
    free(pts);
    return inside;
}

/* What is left of the normal relative velocity goes, as when support
 * begins on one contact: from b alone when the partner is static or
 * resting, else shared by inverse mass, the partner taking the opposite
 * change, so that momentum is kept (a box leaning on a 10 kg box that
 * slid past it took the other's speed along the normal, 1 kg m/s from
 * nowhere). */
static int settle_joint(vrWorld *w, vrUpdate *up, vrBody *b, double T, const vrCandidate *c)
{
    vrBody *y = &w->table.obj[c->partner]->body;
    int moving = vrBody_IsFree(y);
    vrBodyState *st, *sy;
    double share = moving ? b->inv_mass / (b->inv_mass + y->inv_mass) : 1, along;
    if (vrUpdate_Bodies(up, b, moving ? y : NULL, T, &st, &sy) != 0) return -1;
    along = vec3_dot(c->n, vec3_sub(st->v, c->partner_velocity));
    st->v = vec3_madd(st->v, -share * along, c->n);
    if (sy) sy->v = vec3_madd(sy->v, b->mass * share * along * y->inv_mass, c->n);
    return 0;
}

/* support begins on every one of the contacts, as for one (SPEC 3.1): the
 * force's normal components go, and what is left of the normal relative
 * velocity */
static int support_all(vrWorld *w, vrUpdate *up, vrBody *b, double T, const vrCandidate *c, int k)
{
    vrBodyState *st;
    int i;
    for (i = 0; i < k; i++) {
        if (!(st = vrUpdate_Body(up, b, T))) return -1;
        if (st->nsupport == VR_MAX_SUPPORTS) break;
        /* b's state again: settling may have added the partner's and moved it */
        if (settle_joint(w, up, b, T, &c[i]) != 0 || !(st = vrUpdate_Body(up, b, T))) return -1;
        st->support[st->nsupport].partner = c[i].partner;
        st->support[st->nsupport].n = c[i].n;
        st->support[st->nsupport].joint = 1;
        st->support[st->nsupport].fixed = w->table.obj[c[i].partner]->body.is_static;
        st->nsupport++;
    }
    return 0;
}

/* the joint supports of a body whose contacts no longer carry it end */
static int drop_joint(vrUpdate *up, vrBody *b, double T)
{
    vrBodyState *st = vrUpdate_Body(up, b, T);
    int i, k = 0;
    if (!st) return -1;
    for (i = 0; i < st->nsupport; i++)
        if (!st->support[i].joint) st->support[k++] = st->support[i];
    st->nsupport = k;
    return 0;
}

/* one body and its candidates: keep, begin or end support by them together */
static int decide(vrWorld *w, vrUpdate *up, double T, vec3 g, const vrCandidate *c, int k)
{
    vrBody *b = &w->table.obj[c[0].body]->body;
    int held = joint_supports(b) > 0, carry = k >= 2 && carried(w, c, k, g, T);
    if (held && !carry) return drop_joint(up, b, T);
    if (!held && carry) return support_all(w, up, b, T, c, k);
    return 0;
}

int vrRest_SeveralSupports(vrWorld *w, double T, const vrOwnerSet *owners, vrUpdate *up, char *err, size_t n)
{
    vrCandidates list = {0, 0, NULL};
    vec3 g = vrSettings_Flight(&w->s).accel;
    unsigned char *want;
    int count, i, j, r = 0;
    if (vec3_len2(g) == 0) return 0;
    want = wanted(w, &count);
    if (!want) return snprintf(err, n, "out of memory"), -1;
    if (count > 0) r = owners->support_candidates(w, T, want, &list, err, n);
    free(want);
    if (r != 0) {
        vrCandidates_Free(&list);
        return r;
    }
    if (list.n > 1) qsort(list.c, (size_t)list.n, sizeof *list.c, by_body);
    for (i = 0; i < list.n && r == 0; i = j) {
        for (j = i; j < list.n && list.c[j].body == list.c[i].body; j++)
            ;
        r = decide(w, up, T, g, list.c + i, j - i);
    }
    /* jointly carried bodies with no candidate left at all */
    for (i = 0; i < w->table.n && r == 0; i++) {
        vrObject *o = w->table.obj[i];
        int k;
        if (!o || !o->live || o->body.resting || joint_supports(&o->body) == 0) continue;
        for (k = 0; k < list.n && list.c[k].body != i; k++)
            ;
        if (k == list.n) r = drop_joint(up, &o->body, T);
    }
    vrCandidates_Free(&list);
    return r == 0 ? 0 : (snprintf(err, n, "out of memory"), -1);
}
