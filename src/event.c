/* event.c — capturing and applying a body's state: the payload of the
 * thesis's update message (3.5.2).  Every holder applies the same state with
 * the same code, so every copy of a body moves the same bits. */
#include <stdlib.h>
#include "event.h"
#include "grow.h"

/* a merge of at most this many states searches for each (no table) */
#define MERGE_SEARCHED 16

void vrUpdate_Init(vrUpdate *u)
{
    u->n = u->cap = 0;
    u->body = NULL;
}

void vrUpdate_Free(vrUpdate *u)
{
    free(u->body);
    vrUpdate_Init(u);
}

void vrBodyState_Jolt(vrBodyState *st, vec3 accel)
{
    st->hit = 1;
    if (st->contact && vec3_dot(st->v, accel) < 0) st->contact = 0, st->island = -1;
}

void vrBody_Capture(vrBody *b, double t, vrBodyState *st)
{
    vrPose p;
    vrBody_Pose(b, t, &p);
    st->id = b->id;
    st->t = t;
    st->x = p.p;
    st->q = p.q;
    vrBody_Velocity(b, t, &st->v);
    st->L = b->m.L;
    st->raw = 0;
    st->resting = b->resting;
    st->hit = b->hit;
    st->contact = b->contact;
    st->island = b->island;
    st->kinematic = b->kinematic;
    st->clamped = 0;
}

void vrBody_CaptureAnchor(const vrBody *b, vrBodyState *st)
{
    st->id = b->id;
    st->t = b->m.t0;
    st->x = b->m.x0;
    st->v = b->m.v0;
    st->q = b->m.q0;
    st->L = b->m.L;
    st->raw = 1;
    st->resting = b->resting;
    st->hit = b->hit;
    st->contact = b->contact;
    st->island = b->island;
    st->kinematic = b->kinematic;
    st->clamped = 0;
}

vrBodyState *vrUpdate_Find(const vrUpdate *u, int n, int id)
{
    int i;
    for (i = 0; i < n && i < u->n; i++)
        if (u->body[i].id == id) return &u->body[i];
    return NULL;
}

vrBodyState *vrUpdate_Body(vrUpdate *u, vrBody *b, double t)
{
    vrBodyState *st = vrUpdate_Find(u, u->n, b->id);
    return st ? st : vrUpdate_Append(u, b, t);
}

vrBodyState *vrUpdate_Append(vrUpdate *u, vrBody *b, double t)
{
    if (vrGrow((void **)&u->body, &u->cap, u->n + 1, sizeof *u->body) != 0) return NULL;
    vrBody_Capture(b, t, &u->body[u->n]);
    return &u->body[u->n++];
}

int vrUpdate_AppendStates(vrUpdate *to, const vrUpdate *from)
{
    int i;
    for (i = 0; i < from->n; i++) {
        if (vrGrow((void **)&to->body, &to->cap, to->n + 1, sizeof *to->body) != 0) return -1;
        to->body[to->n++] = from->body[i];
    }
    return 0;
}

/* the slot of each id in u (its first, as vrUpdate_Body finds), -1 if none */
static int *slots_of(const vrUpdate *u, int nid)
{
    int *slot = malloc(((size_t)nid + 1) * sizeof *slot), i;
    if (!slot) return NULL;
    for (i = 0; i <= nid; i++) slot[i] = -1;
    for (i = u->n - 1; i >= 0; i--)
        if (u->body[i].id >= 0 && u->body[i].id < nid) slot[u->body[i].id] = i;
    return slot;
}

int vrUpdate_Merge(vrUpdate *to, const vrUpdate *from, int nid)
{
    int *slot, i;
    if (from->n <= MERGE_SEARCHED) {
        for (i = 0; i < from->n; i++) {
            int k;
            for (k = 0; k < to->n && to->body[k].id != from->body[i].id; k++) continue;
            if (k == to->n && vrGrow((void **)&to->body, &to->cap, to->n + 1, sizeof *to->body) != 0) return -1;
            if (k == to->n) to->n++;
            to->body[k] = from->body[i];
        }
        return 0;
    }
    if (!(slot = slots_of(to, nid))) return -1;
    for (i = 0; i < from->n; i++) {
        int id = from->body[i].id, k = id >= 0 && id < nid ? slot[id] : -1;
        if (k < 0) {
            if (vrGrow((void **)&to->body, &to->cap, to->n + 1, sizeof *to->body) != 0) {
                free(slot);
                return -1;
            }
            k = to->n++;
            if (id >= 0 && id < nid) slot[id] = k;
        }
        to->body[k] = from->body[i];
    }
    free(slot);
    return 0;
}

int vrUpdate_Bodies(vrUpdate *u, vrBody *x, vrBody *y, double t, vrBodyState **sx, vrBodyState **sy)
{
    if ((y && !vrUpdate_Body(u, y, t)) || !vrUpdate_Body(u, x, t)) return -1;
    *sx = vrUpdate_Body(u, x, t);   /* found again: nothing added, nothing moved */
    *sy = y ? vrUpdate_Body(u, y, t) : NULL;
    return 0;
}

int vrBody_Apply(vrBody *b, const vrBodyState *st, const vrFlight *f)
{
    b->resting = st->resting;
    b->hit = st->hit;
    b->contact = st->contact;
    b->island = st->island;
    b->kinematic = st->kinematic;
    if (st->raw) {
        vrBody_Restore(b, st->t, st->x, st->v, st->q, st->L, f);
        return st->clamped;
    }
    return st->clamped + vrBody_Anchor(b, st->t, st->x, st->v, st->q, st->L, f);
}

vrTouch *vrTouches_Add(vrTouches *l)
{
    if (vrGrow((void **)&l->t, &l->cap, l->n + 1, sizeof *l->t) != 0) return NULL;
    return &l->t[l->n++];
}

void vrTouches_Free(vrTouches *l)
{
    free(l->t);
    l->t = NULL;
    l->n = l->cap = 0;
}
