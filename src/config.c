/* config.c — settings and object definitions: defaults, checks, and the
 * parameters the settings give the pair owners.
 *
 *   bad_range     outside [lo, hi] (or at lo when lo is open), or not finite
 *   out_of_range  the error "what must be range (got v)"
 */
#include <string.h>
#include "config.h"

vrObjectDef vrObjectDef_Default(vrObjectType type)
{
    vrObjectDef d;
    memset(&d, 0, sizeof d);
    d.type = type;
    d.elasticity = 1.0;
    d.mass = 1.0;
    d.volume = 1.0;
    d.rotate_axis[2] = 1.0;
    d.color[0] = 255;
    d.radius = 1.0;
    d.ures = d.vres = 10;
    d.size[0] = d.size[1] = d.size[2] = 1.0;
    d.exp1 = d.exp2 = 1.0;
    d.a1 = d.a2 = d.a3 = 1.0;
    return d;
}

vrSettings vrSettings_Default(void)
{
    vrSettings s;
    memset(&s, 0, sizeof s);
    s.time_step = 0.1;
    s.collision_dist = 0.25;
    s.max_linear = 8.0;
    s.max_angular = 4.0;
    s.force_dir[2] = -1.0;
    s.heap = 1;
    s.max_frames = 600;
    s.distribution = VR_DIST_ROUND_ROBIN;
    strcpy(s.lcm_url, "udpm://239.255.76.67:7667?ttl=0");
    s.collision_vol = 1.0;
    s.default_elasticity = 1.0;
    s.contact_step = 1.0 / 240;
    s.sound_min_speed = 0.5;
    return s;
}

static int bad_range(double v, double lo, double hi, int lo_open)
{
    return !isfinite(v) || v > hi || v < lo || (lo_open && v == lo);
}

static int out_of_range(char *err, size_t n, const char *what, const char *range, double v)
{
    return vrGeom_Fail(err, n, "%s must be %s (got %g)", what, range, v);
}

int vrSettings_Check(const vrSettings *s, char *err, size_t n)
{
    vec3 f = vrVec3_Of(s->force_dir);
    if (bad_range(s->time_step, 0, 1e9, 0)) return out_of_range(err, n, "time_step", ">= 0", s->time_step);
    if (bad_range(s->collision_dist, 0, 1e9, 1)) return out_of_range(err, n, "collision_dist", "> 0", s->collision_dist);
    if (bad_range(s->internal_step, 0, 1e9, 0)) return out_of_range(err, n, "internal_step", ">= 0", s->internal_step);
    if (bad_range(s->max_linear, 0, 1e9, 1)) return out_of_range(err, n, "max_linear", "> 0", s->max_linear);
    if (bad_range(s->max_angular, 0, 1e9, 1)) return out_of_range(err, n, "max_angular", "> 0", s->max_angular);
    if (!vec3_isfinite(f) || vec3_len2(f) == 0) return vrGeom_Fail(err, n, "force direction must be a non-zero vector");
    if (bad_range(s->force_mag, 0, 1e9, 0)) return out_of_range(err, n, "force magnitude", ">= 0", s->force_mag);
    if (s->heap != 0 && s->heap != 1) return out_of_range(err, n, "heap", "0 or 1", s->heap);
    if (s->max_frames < 0) return out_of_range(err, n, "max_frames", ">= 0", s->max_frames);
    if (bad_range(s->room, 0, 1e6, 0)) return out_of_range(err, n, "room", ">= 0", s->room);
    if (s->gps < 0 || s->gps > VR_MAX_GPS) return vrGeom_Fail(err, n, "%s must be 0..%d (got %g)", "gps", VR_MAX_GPS, (double)s->gps);
    if (bad_range(s->collision_vol, 0, 1, 0)) return out_of_range(err, n, "collision_vol", "0..1", s->collision_vol);
    if (bad_range(s->default_friction, 0, 10, 0)) return out_of_range(err, n, "default_friction", "0..10", s->default_friction);
    if (bad_range(s->default_elasticity, 0, 1, 0))
        return out_of_range(err, n, "default_elasticity", "0..1", s->default_elasticity);
    if (bad_range(s->contact_step, 1e-5, 0.1, 0)) return out_of_range(err, n, "contact_step", "1e-5..0.1", s->contact_step);
    if (bad_range(s->sound_min_speed, 0, 1e9, 0)) return out_of_range(err, n, "sound_min_speed", ">= 0", s->sound_min_speed);
    return 0;
}

int vrObjectDef_Check(const vrObjectDef *d, char *err, size_t n)
{
    vec3 axis = vrVec3_Of(d->rotate_axis);
    int i;
    for (i = 0; i < 3; i++) {
        if (!isfinite(d->linear_vel[i]) || !isfinite(d->angular_vel[i]) || !isfinite(d->translate[i]))
            return vrGeom_Fail(err, n, "vectors must be finite");
        if (d->color[i] < 0 || d->color[i] > 255) return out_of_range(err, n, "color", "0..255", d->color[i]);
        if (bad_range(d->size[i], 0, 1e9, 1)) return out_of_range(err, n, "size", "> 0", d->size[i]);
    }
    if (bad_range(d->elasticity, 0, 1, 0)) return out_of_range(err, n, "elasticity", "0..1", d->elasticity);
    if (bad_range(d->friction, 0, 10, 0)) return out_of_range(err, n, "friction", "0..10", d->friction);
    if (!isfinite(d->mass) || d->mass == 0) return out_of_range(err, n, "mass", "non-zero", d->mass);
    if (bad_range(d->volume, 0, 1e12, 1)) return out_of_range(err, n, "volume", "> 0", d->volume);
    if (d->rotate_set && (!isfinite(d->rotate_angle) || !vec3_isfinite(axis) || vec3_len2(axis) == 0))
        return vrGeom_Fail(err, n, "rotate axis must be a non-zero vector");
    if (bad_range(d->radius, 0, 1e9, 1)) return out_of_range(err, n, "radius", "> 0", d->radius);
    if (d->ures < 3 || d->ures > 1000) return out_of_range(err, n, "ures", "3..1000", d->ures);
    if (d->vres < 3 || d->vres > 1000) return out_of_range(err, n, "vres", "3..1000", d->vres);
    if (bad_range(d->exp1, 0.05, 2, 0)) return out_of_range(err, n, "exp1", "0.05..2", d->exp1);
    if (bad_range(d->exp2, 0.05, 2, 0)) return out_of_range(err, n, "exp2", "0.05..2", d->exp2);
    if (bad_range(d->a1, 0, 1e9, 1)) return out_of_range(err, n, "a1", "> 0", d->a1);
    if (bad_range(d->a2, 0, 1e9, 1)) return out_of_range(err, n, "a2", "> 0", d->a2);
    if (bad_range(d->a3, 0, 1e9, 1)) return out_of_range(err, n, "a3", "> 0", d->a3);
    return 0;
}

vrFlight vrSettings_Flight(const vrSettings *s)
{
    vrFlight f;
    f.accel = vec3_scale(vec3_normalize(vrVec3_Of(s->force_dir)), s->force_mag);
    f.max_linear = s->max_linear;
    f.max_angular = s->max_angular;
    return f;
}

vrParams vrSettings_Params(const vrSettings *s)
{
    vrParams p;
    p.d = s->collision_dist;
    p.flight = vrSettings_Flight(s);
    p.use_heap = s->heap;
    return p;
}

int vrSettings_Changes(const vrSettings *a, const vrSettings *b)
{
    if (a->collision_dist != b->collision_dist || a->max_linear != b->max_linear
        || a->max_angular != b->max_angular || a->force_mag != b->force_mag
        || a->force_dir[0] != b->force_dir[0] || a->force_dir[1] != b->force_dir[1]
        || a->force_dir[2] != b->force_dir[2])
        return VR_PARAMS_OWNERS | VR_PARAMS_MOTION;
    return a->heap != b->heap ? VR_PARAMS_OWNERS : 0;
}
