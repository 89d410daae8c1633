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
#include "rest.h"
#include "start.h"

static int motion_edited(const vrObjectDef *a, const vrObjectDef *b)
{
    return memcmp(a->translate, b->translate, sizeof a->translate) != 0
        || memcmp(a->linear_vel, b->linear_vel, sizeof a->linear_vel) != 0
        || memcmp(a->angular_vel, b->angular_vel, sizeof a->angular_vel) != 0
        || a->rotate_set != b->rotate_set || a->rotate_angle != b->rotate_angle
        || memcmp(a->rotate_axis, b->rotate_axis, sizeof a->rotate_axis) != 0;
}

/* the islands an edit of o wakes: its own, or every one for a static
 * body (which islands lie on it is not kept) */
static int woken_by(const vrObject *o) { return o->body.is_static ? VR_EVERY_ISLAND : o->body.island; }

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
        o->body.friction = o->def.friction;
        w->structure++;                  /* workers rebuild it with the new elasticity and friction */
        return 0;
    }
    if (!o->built) w->structure++;
    o->overlap_owed = 1;
    w->table.unready = 1;
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
    st->contact = 0;
    st->island = -1;
    if (vrRest_WakeIsland(w, was_static ? VR_EVERY_ISLAND : woken_by(o), &w->update, w->t) != 0) return vrGeom_Fail(err, n, "out of memory");
    if (was_static != o->body.is_static) {
        if (w->owner) vrOwner_DropBody(w->owner, o->body.id);
        o->live = 0;
        if (vrWorld_MakeLive(w, err, n) != 0) return -1;
    }
    return vrWorld_ApplyUpdate(w, &w->update) == 0 ? 0 : vrGeom_Fail(err, n, "out of memory");
}

int vrWorld_SetObjectDef(vrWorld *w, vrObjectId id, const vrObjectDef *def, char *err, size_t n)
{
    vrObject *o = vrWorld_Object(w, id);
    vrObjectDef old;
    if (!o) return vrGeom_Fail(err, n, "no such object");
    if (vrObject_SetDef(o, def, &old, err, n) != 0) return -1;
    if (vrObjectDef_ShapeChanged(&old, def) || vrObjectDef_MassChanged(&old, def)) o->built = 0, w->table.unready = 1;
    if (!o->live) return 0;
    return apply_live_edit(w, o, &old, err, n);
}

static void drop_state(vrUpdate *u, int id)
{
    int i, k = 0;
    for (i = 0; i < u->n; i++)
        if (u->body[i].id != id) u->body[k++] = u->body[i];
    u->n = k;
}

int vrWorld_DeleteObject(vrWorld *w, vrObjectId id)
{
    vrObject *o = vrWorld_Object(w, id);
    if (!o) return -1;
    if (o->live) {
        /* the island it rested in wakes */
        w->update.n = 0;
        if (vrRest_WakeIsland(w, woken_by(o), &w->update, w->t) != 0) return -1;
        if (w->owner) vrOwner_DropBody(w->owner, id);
        w->table.obj[id] = NULL;
        drop_state(&w->pending, id);
        drop_state(&w->update, id);      /* a resting body wakes with its island: not itself, gone */
        w->structure++;
        if (vrWorld_ApplyUpdate(w, &w->update) != 0) return -1;
    }
    w->table.obj[id] = NULL;
    vrObject_Free(o);
    return vrWorld_ListDynamic(w);
}
