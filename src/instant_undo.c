/* instant_undo.c — the pairwise answers of one instant, taken back
 * (instant_undo.h: why).  What is noted reads only the bodies and the
 * events, which every owner set sees alike, so serial and workers take
 * the same instants back. */
#include <math.h>
#include <stdlib.h>
#include "instant_undo.h"
#include "grow.h"
#include "world_state.h"

void vrInstantLog_Init(vrInstantLog *l)
{
    vrUpdate_Init(&l->before);
    l->order = NULL;
    l->ordercap = 0;
    vrInstantLog_Frame(l);
}

void vrInstantLog_Free(vrInstantLog *l)
{
    vrUpdate_Free(&l->before);
    free(l->order);
    vrInstantLog_Init(l);
}

void vrInstantLog_Frame(vrInstantLog *l)
{
    l->t = NAN;
    l->held = l->together = 0;
    l->collisions = l->clamps = 0;
    l->answers = 0;
    l->before.n = 0;
    l->norder = 0;
}

static int answered(const vrInstantLog *l, long long order)
{
    int i;
    for (i = 0; i < l->norder; i++)
        if (l->order[i] == order) return 1;
    return 0;
}

int vrInstantLog_Note(vrWorld *w, const vrEvent *ev, const vrUpdate *up, int together)
{
    vrInstantLog *l = &w->instant_log;
    int i;
    if (!(ev->t == l->t)) {   /* a new instant */
        vrInstantLog_Frame(l);
        l->t = ev->t;
        l->collisions = w->collisions;
        l->clamps = w->clamps;
    }
    l->answers++;
    if (l->held) {   /* taken back already: once an instant */
        l->held = 2;
        return 0;
    }
    if (together || l->together || ev->kind == VR_EV_PUSHOUT) {   /* a push-out moved bodies: kept */
        l->together = 1;
        return 0;
    }
    if (!answered(l, ev->order)) {
        if (vrGrow((void **)&l->order, &l->ordercap, l->norder + 1, sizeof *l->order) != 0) return -1;
        l->order[l->norder++] = ev->order;
    }
    for (i = 0; i < up->n; i++)
        if (!vrUpdate_Find(&l->before, l->before.n, up->body[i].id) &&
            !vrUpdate_Append(&l->before, &w->table.obj[up->body[i].id]->body, ev->t))
            return -1;
    return 0;
}

/* a dynamic body of ev that the instant's answers changed, the other
 * immovable: the first driven into the second.  With no force nothing
 * lies on anything: the answers stay pairwise, and bounce as a cradle
 * does (held, an elastic stack struck without gravity lost energy) */
int vrInstantLog_Drives(const vrWorld *w, const vrEvent *ev, vec3 accel)
{
    const vrInstantLog *l = &w->instant_log;
    const vrBody *A, *B;
    if (vec3_len2(accel) == 0) return 0;
    if (ev->kind != VR_EV_CONTACT || !(ev->t == l->t) || l->held || l->together || answered(l, ev->order)) return 0;
    A = &w->table.obj[ev->a]->body, B = &w->table.obj[ev->b]->body;
    if (vrBody_Immovable(A) == vrBody_Immovable(B)) return 0;
    return vrUpdate_Find(&l->before, l->before.n, vrBody_Immovable(A) ? ev->b : ev->a) != NULL;
}

int vrInstantLog_Undo(vrWorld *w, vrUpdate *up)
{
    vrInstantLog *l = &w->instant_log;
    int i;
    up->n = 0;
    if (vrUpdate_AppendStates(up, &l->before) != 0) return -1;
    for (i = 0; i < up->n; i++) up->body[i].resting = 0;   /* awake, as the answer taken back left it: its touches are looked at */
    w->collisions = l->collisions;
    w->clamps = l->clamps;
    l->held = 1;
    l->before.n = 0;
    l->norder = 0;
    i = l->answers;
    l->answers = 0;
    return i;
}
