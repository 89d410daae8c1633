/* save_body.c — the sections of a saved file about bodies (save_sections.h):
 *   body     an object's anchor of free flight (time, centre, velocity,
 *            orientation as a quaternion, angular momentum), its rest,
 *            island and contact state, and what the rest test remembers
 *   warm     the last island step's impulses, by pair (warm.h)
 *   pending  a state the owners had not heard of yet
 *   put_state, get_state   the fields of a vrBodyState, both ways
 */
#include <stdio.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "grow.h"
#include "saved.h"
#include "save_sections.h"
#include "rest.h"

static void put_vec(FILE *out, const char *key, vec3 v)
{
    double a[3];
    a[0] = v.x, a[1] = v.y, a[2] = v.z;
    vrSave_Vector(out, key, a, 3);
}

static void put_quat(FILE *out, const char *key, quat q)
{
    double a[4];
    a[0] = q.w, a[1] = q.x, a[2] = q.y, a[3] = q.z;
    vrSave_Vector(out, key, a, 4);
}

static int get_vec(vrSaveLine *l, const char *key, vec3 *v, char *err, size_t n)
{
    double a[3];
    if (vrSaveLine_Numbers(l, key, a, 3, 0, err, n) != 0) return -1;
    *v = vec3_make(a[0], a[1], a[2]);
    return 0;
}

int vrSave_GetQuat(vrSaveLine *l, const char *key, quat *q, char *err, size_t n)
{
    double a[4];
    if (vrSaveLine_Numbers(l, key, a, 4, 0, err, n) != 0) return -1;
    if (fabs(sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2] + a[3] * a[3]) - 1) > 1e-9) {
        snprintf(err, n, "state %s: %s must be a unit quaternion (w, x, y, z)", l->word, key);
        return -1;
    }
    *q = quat_make(a[0], a[1], a[2], a[3]);
    return 0;
}

static int get_int(vrSaveLine *l, const char *key, long long lo, long long hi, int *v, char *err, size_t n)
{
    long long x;
    if (vrSaveLine_Integer(l, key, lo, hi, &x, err, n) != 0) return -1;
    *v = (int)x;
    return 0;
}

static void put_state(FILE *out, const vrBodyState *st)
{
    put_vec(out, "x", st->x);
    put_vec(out, "v", st->v);
    put_quat(out, "q", st->q);
    put_vec(out, "L", st->L);
    vrSave_Integer(out, "rest", st->resting);
    vrSave_Integer(out, "hit", st->hit);
    vrSave_Integer(out, "contact", st->contact);
    vrSave_Integer(out, "island", st->island);
}

/* island: the island's lowest body id, -1 for none; a body in an island
 * is in contact (the frame end's rest test visits the bodies in contact) */
static int get_state(vrSaveLine *l, int max_island, vrBodyState *st, char *err, size_t n)
{
    if (get_vec(l, "x", &st->x, err, n) || get_vec(l, "v", &st->v, err, n) || vrSave_GetQuat(l, "q", &st->q, err, n)
        || get_vec(l, "L", &st->L, err, n) || get_int(l, "rest", 0, 1, &st->resting, err, n)
        || get_int(l, "hit", 0, 1, &st->hit, err, n) || get_int(l, "contact", 0, 1, &st->contact, err, n)
        || get_int(l, "island", -1, max_island, &st->island, err, n))
        return -1;
    if (st->island >= 0 && !st->contact) return snprintf(err, n, "island %d without contact 1", st->island), -1;
    return 0;
}

/* ---- body ------------------------------------------------------------------------- */

/* a body read and not yet started is saved as it was read */
void vrSave_WriteBody(vrWorld *w, int id, FILE *out)
{
    vrObject *o = vrWorld_Object(w, id);
    vrSavedBody s;
    if (o->saved) s = *o->saved;
    else if (o->live) {
        vrBody_CaptureAnchor(&o->body, &s.anchor);
        s.quiet_frames = o->quiet_frames, s.overlap_owed = o->overlap_owed;
        s.slow_frames = o->slow_frames, s.slow_start = o->slow_start;
        vrRest_KeepFramePose(w, o);
        s.have_frame_pose = o->have_frame_pose, s.frame_pose = o->frame_pose;
    } else
        return;                          /* not in the run yet: its definition places it */
    fputs("  state body", out);
    vrSave_Number(out, "t0", s.anchor.t);
    put_state(out, &s.anchor);
    vrSave_Integer(out, "quiet", s.quiet_frames);
    vrSave_Integer(out, "slow", s.slow_frames);
    vrSave_Number(out, "slow_start", s.slow_start);
    vrSave_Integer(out, "owed", s.overlap_owed);
    if (s.have_frame_pose) {
        put_vec(out, "frame_x", s.frame_pose.p);
        put_quat(out, "frame_q", s.frame_pose.q);
    }
    fputc('\n', out);
}

static int read_frame_pose(vrSaveLine *l, vrSavedBody *s, char *err, size_t n)
{
    vec3 p;
    quat q;
    s->have_frame_pose = vrSaveLine_Has(l, "frame_x") || vrSaveLine_Has(l, "frame_q");
    if (!s->have_frame_pose) return 0;
    if (get_vec(l, "frame_x", &p, err, n) || vrSave_GetQuat(l, "frame_q", &q, err, n)) return -1;
    s->frame_pose = vrPose_make(p, q);
    return 0;
}

/* the rest test's slow window (rest.c): files saved before it have none */
static int read_slow(vrSaveLine *l, vrSavedBody *s, char *err, size_t n)
{
    if (!vrSaveLine_Has(l, "slow") && !vrSaveLine_Has(l, "slow_start")) return 0;
    return get_int(l, "slow", 0, 1000000000, &s->slow_frames, err, n)
        || vrSaveLine_Numbers(l, "slow_start", &s->slow_start, 1, 0, err, n) ? -1 : 0;
}

int vrSave_ReadBody(vrWorld *w, int id, vrSaveLine *l, char *err, size_t n)
{
    vrObject *o = vrWorld_Object(w, id);
    vrSavedBody s;
    memset(&s, 0, sizeof s);
    if (!o) {
        snprintf(err, n, "state body: no object selected (it follows its object's definition)");
        return -1;
    }
    s.anchor.raw = 1;
    if (vrSaveLine_Numbers(l, "t0", &s.anchor.t, 1, 0, err, n) || get_state(l, id, &s.anchor, err, n)
        || get_int(l, "quiet", 0, 1000000000, &s.quiet_frames, err, n)
        || read_slow(l, &s, err, n)
        || get_int(l, "owed", 0, 1, &s.overlap_owed, err, n) || read_frame_pose(l, &s, err, n))
        return -1;
    if (!o->saved && !(o->saved = malloc(sizeof *o->saved))) {
        snprintf(err, n, "out of memory");
        return -1;
    }
    *o->saved = s;
    w->table.unready = 1;
    return 0;
}

/* ---- warm ------------------------------------------------------------------------- */

void vrSave_WriteWarm(vrWorld *w, int id, FILE *out)
{
    int i, k;
    (void)id;
    /* stale ones the next step would not use; read ones not started belong to it */
    if (w->warm.structure != w->structure && !(w->resume && w->resume->warm)) return;
    for (i = 0; i < w->warm.n; i++) {
        const vrWarmContact *c = &w->warm.c[i];
        char key[24];
        fprintf(out, "state warm a=%s b=%s", w->table.obj[c->a]->name, w->table.obj[c->b]->name);
        vrSave_Number(out, "h", c->h);
        put_vec(out, "n", c->n);
        vrSave_Integer(out, "points", c->npoints);
        for (k = 0; k < c->npoints; k++) {
            snprintf(key, sizeof key, "p%d", k);
            put_vec(out, key, c->p[k]);
            snprintf(key, sizeof key, "impulse%d", k);
            vrSave_Number(out, key, c->lambda[k]);
        }
        put_vec(out, "friction", c->friction);
        vrSave_Number(out, "twist", c->twist);
        fputc('\n', out);
    }
}

int vrSave_GetObject(vrWorld *w, vrSaveLine *l, const char *key, int *id, char *err, size_t n)
{
    char name[VR_NAME_MAX + 1];
    if (vrSaveLine_Word(l, key, name, sizeof name, err, n) != 0) return -1;
    if ((*id = vrWorld_FindObject(w, name)) != VR_NO_OBJECT) return 0;
    snprintf(err, n, "state %s: no object named '%s' (objects come before this line)", l->word, name);
    return -1;
}

static int read_points(vrSaveLine *l, vrIslandContact *c, char *err, size_t n)
{
    char key[24];
    int k;
    if (get_int(l, "points", 1, VR_ISLAND_POINTS, &c->npoints, err, n) != 0) return -1;
    for (k = 0; k < c->npoints; k++) {
        snprintf(key, sizeof key, "p%d", k);
        if (get_vec(l, key, &c->p[k], err, n) != 0) return -1;
        snprintf(key, sizeof key, "impulse%d", k);
        if (vrSaveLine_Numbers(l, key, &c->lambda[k], 1, 0, err, n) != 0) return -1;
    }
    return 0;
}

int vrSave_ReadWarm(vrWorld *w, int id, vrSaveLine *l, char *err, size_t n)
{
    vrIslandContact c;
    vrResume *r;
    double h;
    int a, b;
    (void)id;
    memset(&c, 0, sizeof c);
    if (vrSave_GetObject(w, l, "a", &a, err, n) || vrSave_GetObject(w, l, "b", &b, err, n)
        || vrSaveLine_Numbers(l, "h", &h, 1, 0, err, n) || get_vec(l, "n", &c.n, err, n) || read_points(l, &c, err, n)
        || get_vec(l, "friction", &c.friction, err, n) || vrSaveLine_Numbers(l, "twist", &c.twist, 1, 0, err, n))
        return -1;
    if (a >= b) {
        snprintf(err, n, "state warm: a must be the object made first");
        return -1;
    }
    if (!(r = vrSave_Resumed(w)) || vrWarm_Keep(&w->warm, a, b, h, &c) != 0) {
        snprintf(err, n, "out of memory");
        return -1;
    }
    r->warm = 1;
    return 0;
}

/* ---- pending ---------------------------------------------------------------------- */

void vrSave_WritePending(vrWorld *w, int id, FILE *out)
{
    const vrUpdate *u = w->resume ? &w->resume->pending : &w->pending;   /* read, not started: as read */
    int i;
    (void)id;
    for (i = 0; i < u->n; i++) {
        const vrBodyState *st = &u->body[i];
        fprintf(out, "state pending obj=%s", w->table.obj[st->id]->name);
        vrSave_Number(out, "t", st->t);
        vrSave_Integer(out, "raw", st->raw);
        put_state(out, st);
        fputc('\n', out);
    }
}

int vrSave_ReadPending(vrWorld *w, int id, vrSaveLine *l, char *err, size_t n)
{
    vrBodyState st;
    vrResume *r;
    (void)id;
    memset(&st, 0, sizeof st);
    if (vrSave_GetObject(w, l, "obj", &st.id, err, n) || vrSaveLine_Numbers(l, "t", &st.t, 1, 0, err, n)
        || get_int(l, "raw", 0, 1, &st.raw, err, n) || get_state(l, st.id, &st, err, n))
        return -1;
    if (!(r = vrSave_Resumed(w))
        || vrGrow((void **)&r->pending.body, &r->pending.cap, r->pending.n + 1, sizeof *r->pending.body) != 0) {
        snprintf(err, n, "out of memory");
        return -1;
    }
    r->pending.body[r->pending.n++] = st;
    return 0;
}
