/* query.c — what the world tells its user (include/vroc.h): an object's
 * state and mesh at the world's time, whether everything rests, and the
 * statistics of SPEC 1.3.
 *
 *   ready         an object built, and placed if not yet in the simulation
 *   motion_state  static, moving, supported or at rest (SPEC 3.5)
 */
#include <string.h>
#include "build.h"
#include "config.h"
#include "shape_share.h"
#include "world_state.h"
#include "parallel/sgp.h"

static int ready(vrWorld *w, vrObject *o)
{
    vrFlight f = vrSettings_Flight(&w->s);
    return vrObject_Ready(o, w->t, &f, NULL, NULL, 0);
}

int vrWorld_AllAtRest(const vrWorld *w)
{
    int i;
    for (i = 0; i < w->table.n; i++) {
        const vrObject *o = w->table.obj[i];
        if (o && !o->body.is_static && !(o->live && o->body.resting)) return 0;
    }
    return 1;
}

static vrMotionState motion_state(const vrBody *b)
{
    if (b->is_static) return VR_STATE_STATIC;
    if (b->resting) return VR_STATE_REST;
    return b->contact ? VR_STATE_SUPPORTED : VR_STATE_MOVING;   /* SPEC 7: in an island's contact step */
}

int vrWorld_GetObjectState(const vrWorld *cw, vrObjectId id, vrObjectState *st)
{
    vrWorld *w = (vrWorld *)cw;   /* pose queries advance the rotation cache */
    vrObject *o = vrWorld_Object(w, id);
    vrPose p;
    vec3 v, om;
    quat q;
    if (!o || ready(w, o) != 0) return -1;
    vrBody_Pose(&o->body, w->t, &p);
    vrBody_Velocity(&o->body, w->t, &v);
    om = vrBody_Omega(&o->body, &p);
    q = quat_canonical(p.q);
    st->t = w->t;
    st->position[0] = p.p.x; st->position[1] = p.p.y; st->position[2] = p.p.z;
    st->orientation[0] = q.w; st->orientation[1] = q.x; st->orientation[2] = q.y; st->orientation[3] = q.z;
    st->linear_vel[0] = v.x; st->linear_vel[1] = v.y; st->linear_vel[2] = v.z;
    st->angular_vel[0] = om.x; st->angular_vel[1] = om.y; st->angular_vel[2] = om.z;
    st->state = motion_state(&o->body);
    return 0;
}

int vrWorld_GetMesh(vrWorld *w, vrObjectId id, vrMesh *m)
{
    vrObject *o = vrWorld_Object(w, id);
    if (!o || ready(w, o) != 0) return -1;
    m->nverts = o->shape->poly->nv;
    m->verts = o->shape->draw_verts;
    m->normals = o->shape->draw_normals;
    m->nfaces = o->shape->poly->nf;
    m->face_start = o->shape->draw_face_start;
    m->face_verts = o->shape->draw_face_verts;
    m->smooth = o->def.type == VR_SPHERE || o->def.type == VR_SUPERQUADRIC;
    return 0;
}

void vrWorld_NoteRenderTime(vrWorld *w, double ms) { w->render_ms += ms; }

void vrWorld_GetStats(const vrWorld *cw, vrStats *st)
{
    vrWorld *w = (vrWorld *)cw;
    int i;
    memset(st, 0, sizeof *st);
    st->frames = w->frames;
    st->time = w->t;
    for (i = 0; i < w->table.n; i++) {
        vrObject *o = w->table.obj[i];
        if (!o) continue;
        st->objects++;
        if (vrObjectDef_Mass(&o->def) > 0) st->dynamic++;
        if (o->live && o->body.resting) st->resting++;
        if (vrObjectDef_Mass(&o->def) > 0 && ready(w, o) == 0)
            st->energy += vrBody_Energy(&o->body, w->t, vrSettings_Flight(&w->s).accel);
    }
    /* SPEC 1.3: dynamic-dynamic plus dynamic-static pairs */
    st->pairs = (long)st->dynamic * (st->dynamic - 1) / 2 + (long)st->dynamic * (st->objects - st->dynamic);
    st->subframes = w->subframes;
    st->subframes_thesis = (long)ceil(w->s.time_step * 2.0 * w->s.max_linear / w->s.collision_dist);
    st->checks = w->retired.checks;
    st->heap_pops = w->retired.heap_pops;
    st->klu_solves = w->retired.response.solves;
    st->klu_refactors = w->retired.response.refactors;
    st->klu_factors = w->retired.response.factors;
    if (w->owner) {
        vrOwnerStats os;
        vrOwner_Stats(w->owner, &os);
        st->checks += os.checks;
        st->heap_pops += os.heap_pops;
        st->klu_solves += os.response.solves;
        st->klu_refactors += os.response.refactors;
        st->klu_factors += os.response.factors;
    }
    if (w->owner) st->live_pairs = vrOwner_PairCount(w->owner);
    if (w->sgp) vrSgp_Stats(w->sgp, st);
    st->collisions = w->collisions;
    st->island_steps = w->island_steps;
    st->island_contacts = w->island_contacts;
    st->clamps = w->clamps;
    st->frame_ms = w->frame_ms;
    st->sim_ms = w->sim_ms;
    st->render_ms = w->render_ms;
}

int vrWorld_FrameSounds(const vrWorld *w, const vrSoundEvent **events)
{
    *events = w->sounds.ev;
    return w->sounds.n;
}
