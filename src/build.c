/* build.c — an object's shape, mass and initial state from its definition.
 *
 *   make_shape   the hull of the definition (a sphere's: its drawing mesh),
 *                shared by the objects of one shape (shape_share.h)
 */
#include <stdlib.h>
#include <string.h>
#include "build.h"
#include "off.h"
#include "shape_share.h"
#include "saved.h"
#include "config.h"

double vrObjectDef_Mass(const vrObjectDef *d) { return d->mass_set ? d->mass : d->volume; }

int vrObjectDef_ShapeChanged(const vrObjectDef *a, const vrObjectDef *b)
{
    switch (b->type) {
    case VR_SPHERE:
        return a->radius != b->radius || a->ures != b->ures || a->vres != b->vres;
    case VR_CUBE:
        return memcmp(a->size, b->size, sizeof a->size) != 0;
    case VR_SUPERQUADRIC:
        return a->exp1 != b->exp1 || a->exp2 != b->exp2 || a->a1 != b->a1 || a->a2 != b->a2 || a->a3 != b->a3
            || a->ures != b->ures || a->vres != b->vres;
    default:
        return strcmp(a->file, b->file) != 0 || memcmp(a->scale, b->scale, sizeof a->scale) != 0;
    }
}

int vrObjectDef_MassChanged(const vrObjectDef *a, const vrObjectDef *b)
{
    return vrObjectDef_Mass(a) != vrObjectDef_Mass(b) || a->elasticity != b->elasticity || a->friction != b->friction;
}

/* the object's shape: shared by every object of the same shape
 * (shape_share.h), an OFF polyhedron its own */
static int make_shape(vrObject *o, char *err, size_t n)
{
    const vrObjectDef *d = &o->def;
    vrSharedShape *s;
    if (d->type != VR_POLYHEDRON) {
        s = vrShape_Share(d, err, n);
    } else {
        if (!o->off) return vrGeom_Fail(err, n, "polyhedron '%s' has no file (file = path.off)", o->name);
        s = vrShape_Own(o->off);
        o->off = NULL;
        if (!s) vrGeom_Fail(err, n, "out of memory");
    }
    if (!s) return -1;
    o->shape = s;
    return 0;
}

int vrObject_Build(vrObject *o, char *err, size_t n)
{
    static unsigned long shapes_made;
    const vrObjectDef *d = &o->def;
    vrShape *sh = &o->body.shape;
    mat33 unit;
    double rin, rout;
    if (d->type != VR_POLYHEDRON || o->off) vrObject_FreeShape(o);
    if (!o->shape && make_shape(o, err, n) != 0) return -1;
    memset(sh, 0, sizeof *sh);
    if (d->type == VR_SPHERE) {
        double i = 0.4 * d->radius * d->radius;     /* a solid sphere: 2/5 m r^2 */
        sh->kind = VR_SHAPE_SPHERE;
        sh->radius = d->radius;
        unit = mat33_diag(i, i, i);
        rin = rout = d->radius;
    } else {
        sh->kind = d->type == VR_CUBE ? VR_SHAPE_BOX : VR_SHAPE_POLY;
        sh->half = vrVec3_Of(d->size);
        sh->poly = o->shape->poly;
        unit = sh->poly->inertia_unit;
        rin = sh->poly->r_in;
        rout = sh->poly->r_out;
    }
    sh->serial = ++shapes_made;
    vrBody_SetMassProperties(&o->body, vrObjectDef_Mass(d), &unit, rin, rout);
    o->body.elasticity = d->elasticity;
    o->body.friction = d->friction;
    o->built = 1;
    return 0;
}

quat vrObjectDef_Orientation(const vrObjectDef *d)
{
    if (!d->rotate_set) return quat_identity();
    return quat_from_axis_angle(vec3_normalize(vrVec3_Of(d->rotate_axis)), d->rotate_angle);
}

vec3 vrBody_MomentumAt(const vrBody *b, quat q, vec3 omega)
{
    vrPose p = vrPose_make(vec3_zero(), q);
    mat33 I = vrBody_InertiaWorld(b, &p);
    return mat33_mulv(&I, omega);
}

int vrObject_Place(vrObject *o, double t, const vrFlight *f)
{
    quat q = vrObjectDef_Orientation(&o->def);
    int clamps;
    o->body.resting = 0;
    o->body.contact = 0;
    o->body.island = -1;
    o->body.hit = 0;
    clamps = vrBody_Anchor(&o->body, t, vrVec3_Of(o->def.translate), vrVec3_Of(o->def.linear_vel), q,
                           vrBody_MomentumAt(&o->body, q, vrVec3_Of(o->def.angular_vel)), f);
    o->have_frame_pose = o->frame_pose_lazy = 0;
    if (!o->saved) return clamps;
    vrSaved_Place(o, f);   /* SPEC 11: a saved run goes on where it was */
    return 0;              /* its definition's speeds were cut, and counted, when it was placed first */
}

int vrObject_Ready(vrObject *o, double t, const vrFlight *f, long long *clamps, char *err, size_t n)
{
    if (!o->built) {
        if (vrObject_Build(o, err, n) != 0) return -1;
        if (o->live) return 0;
    }
    if (!o->live) {
        int k = vrObject_Place(o, t, f);
        if (clamps) *clamps += k;
    }
    return 0;
}
