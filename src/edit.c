/* edit.c — objects edited or deleted: a definition edited while the
 * simulation runs acts on the live body at the world's time (the start of
 * the next frame); a deleted object's pairs go, and what rested on it
 * loses that support.
 *
 *   motion_edited        did the position, orientation or a velocity change?
 *   update_supported_by  the states of the bodies an object supports, changed
 *   apply_live_edit      an edit acts on a live body
 */
#include <string.h>
#include "build.h"
#include "config.h"
#include "owners.h"
#include "start.h"

static int motion_edited(const vrObjectDef *a, const vrObjectDef *b)
{
    return memcmp(a->translate, b->translate, sizeof a->translate) != 0
        || memcmp(a->linear_vel, b->linear_vel, sizeof a->linear_vel) != 0
        || memcmp(a->angular_vel, b->angular_vel, sizeof a->angular_vel) != 0
        || a->rotate_set != b->rotate_set || a->rotate_angle != b->rotate_angle
        || memcmp(a->rotate_axis, b->rotate_axis, sizeof a->rotate_axis) != 0;
}

/* Adds to w->update the state of every live body that id supports, and
 * lets fn change it (j: the support on id).  The update's records move
 * as it grows: take none before. */
static int update_supported_by(vrWorld *w, int id, void (*fn)(const vrWorld *w, vrBodyState *st, int j))
{
    int i, j;
    for (i = 0; i < w->table.n; i++) {
        vrObject *x = w->table.obj[i];
        vrBodyState *st;
        if (!x || i == id || !x->live) continue;
        for (j = 0; j < x->body.nsupport && x->body.support[j].partner != id; j++)
            ;
        if (j == x->body.nsupport) continue;
        st = vrUpdate_Body(&w->update, &x->body, w->t);
        if (!st) return -1;
        for (j = 0; j < st->nsupport && st->support[j].partner != id; j++)
            ;
        if (j < st->nsupport) fn(w, st, j);
    }
    return 0;
}

static void drop_support(const vrWorld *w, vrBodyState *st, int j)
{
    int partner = st->support[j].partner, k;
    (void)w;
    for (j = k = 0; j < st->nsupport; j++)
        if (st->support[j].partner != partner) st->support[k++] = st->support[j];
    st->nsupport = k;
    st->resting = 0;
}

/* a partner made static (or dynamic) by an edit: the support's `fixed`
 * (hold_to_supports in effect.c) follows, and a body resting on it wakes */
static void refix_support(const vrWorld *w, vrBodyState *st, int j)
{
    st->support[j].fixed = w->table.obj[st->support[j].partner]->body.is_static;
    st->resting = 0;
}

/* a definition edited while the simulation runs acts on the live body at
 * the world's time (the start of the next frame): a new shape or mass keeps
 * pose and velocities; an edited position or velocity replaces the current
 * one.  An edit wakes the body and what rests on it. */
static int apply_live_edit(vrWorld *w, vrObject *o, const vrObjectDef *old, char *err, size_t n)
{
    vrBodyState *st;
    vrPose pose;
    vec3 omega;
    int was_static = o->body.is_static;
    if (o->built && !motion_edited(old, &o->def)) {
        o->body.elasticity = o->def.elasticity;
        w->structure++;                  /* workers rebuild it with the new elasticity */
        return 0;
    }
    if (!o->built) w->structure++;
    o->overlap_owed = 1;
    vrBody_Pose(&o->body, w->t, &pose);
    omega = vrBody_Omega(&o->body, &pose);
    w->update.n = 0;
    st = vrUpdate_Body(&w->update, &o->body, w->t);
    if (!st) return vrGeom_Fail(err, n, "out of memory");
    if (!o->built && vrObject_Build(o, err, n) != 0) return -1;
    if (memcmp(old->translate, o->def.translate, sizeof old->translate) != 0) st->x = vrVec3_Of(o->def.translate);
    if (old->rotate_set != o->def.rotate_set || old->rotate_angle != o->def.rotate_angle
        || memcmp(old->rotate_axis, o->def.rotate_axis, sizeof old->rotate_axis) != 0)
        st->q = vrObjectDef_Orientation(&o->def);
    if (memcmp(old->linear_vel, o->def.linear_vel, sizeof old->linear_vel) != 0) st->v = vrVec3_Of(o->def.linear_vel);
    if (memcmp(old->angular_vel, o->def.angular_vel, sizeof old->angular_vel) != 0) omega = vrVec3_Of(o->def.angular_vel);
    st->L = vrBody_MomentumAt(&o->body, st->q, omega);
    st->resting = 0;
    st->nsupport = 0;
    if (was_static != o->body.is_static) {
        if (w->owner) vrOwner_DropBody(w->owner, o->body.id);
        o->live = 0;
        if (vrWorld_MakeLive(w, err, n) != 0) return -1;
        if (update_supported_by(w, o->body.id, refix_support) != 0) return vrGeom_Fail(err, n, "out of memory");
    }
    return vrWorld_ApplyUpdate(w, &w->update) == 0 ? 0 : vrGeom_Fail(err, n, "out of memory");
}

int vrWorld_SetObjectDef(vrWorld *w, vrObjectId id, const vrObjectDef *def, char *err, size_t n)
{
    vrObject *o = vrWorld_Object(w, id);
    vrObjectDef old;
    if (!o) return vrGeom_Fail(err, n, "no such object");
    if (vrObject_SetDef(o, def, &old, err, n) != 0) return -1;
    if (vrObjectDef_ShapeChanged(&old, def) || vrObjectDef_MassChanged(&old, def)) o->built = 0;
    if (!o->live) return 0;
    return apply_live_edit(w, o, &old, err, n);
}

static void drop_pending(vrWorld *w, int id)
{
    int i, k = 0;
    for (i = 0; i < w->pending.n; i++)
        if (w->pending.body[i].id != id) w->pending.body[k++] = w->pending.body[i];
    w->pending.n = k;
}

int vrWorld_DeleteObject(vrWorld *w, vrObjectId id)
{
    vrObject *o = vrWorld_Object(w, id);
    if (!o) return -1;
    if (o->live) {
        /* what rests on or slides over it loses that support */
        w->update.n = 0;
        if (update_supported_by(w, id, drop_support) != 0) return -1;
        if (w->owner) vrOwner_DropBody(w->owner, id);
        w->table.obj[id] = NULL;
        drop_pending(w, id);
        w->structure++;
        if (vrWorld_ApplyUpdate(w, &w->update) != 0) return -1;
    }
    w->table.obj[id] = NULL;
    vrObject_Free(o);
    return vrWorld_ListDynamic(w);
}
