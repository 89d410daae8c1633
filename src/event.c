/* event.c — capturing and applying a body's state: the payload of the
 * thesis's update message (3.5.2).  Every holder applies the same state with
 * the same code, so every copy of a body moves the same bits. */
#include <stdlib.h>
#include "event.h"
#include "grow.h"

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

vrBodyState *vrUpdate_Body(vrUpdate *u, vrBody *b, double t)
{
    int i;
    for (i = 0; i < u->n; i++)
        if (u->body[i].id == b->id) return &u->body[i];
    if (vrGrow((void **)&u->body, &u->cap, u->n + 1, sizeof *u->body) != 0) return NULL;
    vrBody_Capture(b, t, &u->body[u->n]);
    return &u->body[u->n++];
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
