/* config.c — settings and object definitions: defaults, checks, and the
 * parameters the settings give the pair owners.
 *
 *   bad_range     outside [lo, hi] (or at lo when lo is open), or not finite
 *   out_of_range  the error "what must be range (got v)"
 *   check_lcm_url, check_times, check_common   parts of the checks
 * The limits are vroc.h's VR_*_MIN/MAX (SPEC 11, man vroc LIMITS).
 */
#include <stdio.h>
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
    d.scale[0] = d.scale[1] = d.scale[2] = 1.0;
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
    s.keep_looks = 1;
    s.broadphase = VR_BROADPHASE_TREE;
    s.max_frames = 600;
    s.distribution = VR_DIST_ROUND_ROBIN;
    strcpy(s.lcm_url, "udpm://239.255.76.67:7667?ttl=0");
    s.collision_vol = 1.0;
    s.default_elasticity = 1.0;
    s.contact_step = 1.0 / 240;
    s.rest_speed = 0.05;
    s.sound_min_speed = 0.5;
    s.grab_reach = 0.1;
    s.fly_speed = 1.0;
    s.hand_min_cutoff = 1.0;
    s.hand_beta = 10.0;
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

/* a length: VR_LENGTH_MIN..VR_LENGTH_MAX m */
static int bad_length(double v) { return bad_range(v, VR_LENGTH_MIN, VR_LENGTH_MAX, 0); }

/* each component of a vector within -lim..lim */
static int bad_vector(const double v[3], double lim)
{
    return bad_range(v[0], -lim, lim, 0) || bad_range(v[1], -lim, lim, 0) || bad_range(v[2], -lim, lim, 0);
}

/* SPEC 11: udpm://GROUP:PORT[?options] with a multicast group
 * (224-239.x.x.x), or memq:// (the workers in this process, spawn.c): a
 * bad URL is refused here, not blamed later on a missing route */
static int check_lcm_url(const char *url, char *err, size_t n)
{
    unsigned a, b, c, d, port;
    char end = 0;
    if (strncmp(url, "memq://", 7) == 0) return 0;
    /* NOLINTNEXTLINE(cert-err34-c): widths bound each field, and the ranges below refuse what sscanf cannot */
    if (sscanf(url, "udpm://%3u.%3u.%3u.%3u:%5u%c", &a, &b, &c, &d, &port, &end) < 5 || (end && end != '?')
        || a < 224 || a > 239 || b > 255 || c > 255 || d > 255 || port == 0 || port > 65535)
        return vrGeom_Fail(err, n, "lcm_url must be memq:// or udpm://GROUP:PORT[?options] with a multicast "
                                   "GROUP 224.0.0.0..239.255.255.255 and a PORT 1..65535 (got '%.200s')", url);
    return 0;
}

/* the time fields: time_step, internal_step (a frame's grid of internal
 * steps is bounded: VR_FRAME_STEPS_MAX), contact_step */
static int check_times(const vrSettings *s, char *err, size_t n)
{
    if (bad_range(s->time_step, 0, VR_TIME_MAX, 0)) return out_of_range(err, n, "time_step", "0..1000 s", s->time_step);
    if (bad_range(s->internal_step, 0, VR_TIME_MAX, 0))
        return out_of_range(err, n, "internal_step", "0..1000 s", s->internal_step);
    if (s->internal_step > 0 && s->time_step / s->internal_step > VR_FRAME_STEPS_MAX)
        return vrGeom_Fail(err, n, "internal_step %g s would make %.3g internal steps a frame of time_step %g s "
                                   "(at most %d): raise internal_step or lower time_step",
                           s->internal_step, s->time_step / s->internal_step, s->time_step, VR_FRAME_STEPS_MAX);
    if (bad_range(s->contact_step, 1e-5, 0.1, 0)) return out_of_range(err, n, "contact_step", "1e-5..0.1", s->contact_step);
    if (bad_range(s->rest_speed, 0, 10, 0)) return out_of_range(err, n, "rest_speed", "0..10", s->rest_speed);
    return 0;
}

/* the hand's select mode (SPEC 8, grab.h) */
static int check_hand(const vrSettings *s, char *err, size_t n)
{
    if (s->select != 0 && s->select != 1) return out_of_range(err, n, "select", "0 or 1", s->select);
    if (bad_range(s->grab_reach, 0, 10, 0)) return out_of_range(err, n, "grab_reach", "0..10 m", s->grab_reach);
    if (bad_range(s->fly_speed, 0, VR_SPEED_MAX, 0)) return out_of_range(err, n, "fly_speed", "0..1e6 m/s", s->fly_speed);
    if (s->hand_filter != 0 && s->hand_filter != 1) return out_of_range(err, n, "hand_filter", "0 or 1", s->hand_filter);
    if (bad_range(s->hand_min_cutoff, 1e-3, 1e3, 0))
        return out_of_range(err, n, "hand_min_cutoff", "1e-3..1e3 Hz", s->hand_min_cutoff);
    if (bad_range(s->hand_beta, 0, 1e6, 0)) return out_of_range(err, n, "hand_beta", "0..1e6 s/m", s->hand_beta);
    return 0;
}

int vrSettings_Check(const vrSettings *s, char *err, size_t n)
{
    vec3 f = vrVec3_Of(s->force_dir);
    if (check_times(s, err, n) != 0) return -1;
    if (bad_length(s->collision_dist)) return out_of_range(err, n, "collision_dist", "1e-6..1e6 m", s->collision_dist);
    if (bad_range(s->max_linear, 0, VR_SPEED_MAX, 1)) return out_of_range(err, n, "max_linear", "> 0, at most 1e6 m/s", s->max_linear);
    if (bad_range(s->max_angular, 0, VR_SPEED_MAX, 1))
        return out_of_range(err, n, "max_angular", "> 0, at most 1e6 rad/s", s->max_angular);
    if (!vec3_isfinite(f) || vec3_len2(f) == 0) return vrGeom_Fail(err, n, "force direction must be a non-zero vector");
    if (bad_range(s->force_mag, 0, VR_ACCEL_MAX, 0)) return out_of_range(err, n, "force magnitude", "0..1e6 m/s^2", s->force_mag);
    if (s->heap != 0 && s->heap != 1) return out_of_range(err, n, "heap", "0 or 1", s->heap);
    if (s->keep_looks != 0 && s->keep_looks != 1) return out_of_range(err, n, "keep_looks", "0 or 1", s->keep_looks);
    if (s->broadphase != VR_BROADPHASE_SWEEP && s->broadphase != VR_BROADPHASE_TREE)
        return vrGeom_Fail(err, n, "broadphase must be sweep or tree");
    if (s->max_frames < 0) return out_of_range(err, n, "max_frames", ">= 0", s->max_frames);
    if (bad_range(s->room, 0, VR_LENGTH_MAX, 0)) return out_of_range(err, n, "room", "0..1e6 m", s->room);
    if (s->gps < 0 || s->gps > VR_MAX_GPS) return vrGeom_Fail(err, n, "%s must be 0..%d (got %g)", "gps", VR_MAX_GPS, (double)s->gps);
    if (check_lcm_url(s->lcm_url, err, n) != 0) return -1;
    if (bad_range(s->collision_vol, 0, 1, 0)) return out_of_range(err, n, "collision_vol", "0..1", s->collision_vol);
    if (bad_range(s->default_friction, 0, 10, 0)) return out_of_range(err, n, "default_friction", "0..10", s->default_friction);
    if (bad_range(s->default_elasticity, 0, 1, 0))
        return out_of_range(err, n, "default_elasticity", "0..1", s->default_elasticity);
    if (bad_range(s->sound_min_speed, 0, VR_SPEED_MAX, 0))
        return out_of_range(err, n, "sound_min_speed", "0..1e6 m/s", s->sound_min_speed);
    if (s->panel != 0 && s->panel != 1) return out_of_range(err, n, "panel", "0 or 1", s->panel);
    return check_hand(s, err, n);
}

/* the pose, velocities, colour and mass of any object */
static int check_common(const vrObjectDef *d, char *err, size_t n)
{
    vec3 axis = vrVec3_Of(d->rotate_axis);
    int i;
    if (bad_vector(d->translate, VR_LENGTH_MAX)) return vrGeom_Fail(err, n, "translate: each component must be -1e6..1e6 m");
    if (bad_vector(d->linear_vel, VR_SPEED_MAX)) return vrGeom_Fail(err, n, "linear_vel: each component must be -1e6..1e6 m/s");
    if (bad_vector(d->angular_vel, VR_SPEED_MAX))
        return vrGeom_Fail(err, n, "angular_vel: each component must be -1e6..1e6 rad/s");
    for (i = 0; i < 3; i++)
        if (d->color[i] < 0 || d->color[i] > 255) return out_of_range(err, n, "color", "0..255", d->color[i]);
    if (bad_range(d->elasticity, 0, 1, 0)) return out_of_range(err, n, "elasticity", "0..1", d->elasticity);
    if (bad_range(d->friction, 0, 10, 0)) return out_of_range(err, n, "friction", "0..10", d->friction);
    /* a static object's mass is never used: any negative number says static */
    if (!isfinite(d->mass) || (d->mass >= 0 && bad_range(d->mass, VR_MASS_MIN, VR_MASS_MAX, 0)))
        return out_of_range(err, n, "mass", "negative (static) or 1e-9..1e12 kg", d->mass);
    if (bad_range(d->volume, VR_MASS_MIN, VR_MASS_MAX, 0)) return out_of_range(err, n, "volume", "1e-9..1e12", d->volume);
    if (d->rotate_set && (!isfinite(d->rotate_angle) || !vec3_isfinite(axis) || vec3_len2(axis) == 0))
        return vrGeom_Fail(err, n, "rotate axis must be a non-zero vector");
    return 0;
}

int vrObjectDef_Check(const vrObjectDef *d, char *err, size_t n)
{
    int i;
    if (check_common(d, err, n) != 0) return -1;
    for (i = 0; i < 3; i++) {
        if (bad_length(d->size[i])) return out_of_range(err, n, "size", "1e-6..1e6 m", d->size[i]);
        if (bad_range(d->scale[i], VR_SCALE_MIN, VR_SCALE_MAX, 0)) return out_of_range(err, n, "scale", "1e-6..1e6", d->scale[i]);
    }
    if (bad_length(d->radius)) return out_of_range(err, n, "radius", "1e-6..1e6 m", d->radius);
    if (d->ures < 3 || d->ures > 1000) return out_of_range(err, n, "ures", "3..1000", d->ures);
    if (d->vres < 3 || d->vres > 1000) return out_of_range(err, n, "vres", "3..1000", d->vres);
    if (bad_range(d->exp1, 0.05, 2, 0)) return out_of_range(err, n, "exp1", "0.05..2", d->exp1);
    if (bad_range(d->exp2, 0.05, 2, 0)) return out_of_range(err, n, "exp2", "0.05..2", d->exp2);
    if (bad_length(d->a1)) return out_of_range(err, n, "a1", "1e-6..1e6 m", d->a1);
    if (bad_length(d->a2)) return out_of_range(err, n, "a2", "1e-6..1e6 m", d->a2);
    if (bad_length(d->a3)) return out_of_range(err, n, "a3", "1e-6..1e6 m", d->a3);
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
    p.keep_looks = s->keep_looks;
    p.use_tree = s->broadphase == VR_BROADPHASE_TREE;
    return p;
}

int vrSettings_Changes(const vrSettings *a, const vrSettings *b)
{
    if (a->collision_dist != b->collision_dist || a->max_linear != b->max_linear
        || a->max_angular != b->max_angular || a->force_mag != b->force_mag
        || a->force_dir[0] != b->force_dir[0] || a->force_dir[1] != b->force_dir[1]
        || a->force_dir[2] != b->force_dir[2])
        return VR_PARAMS_OWNERS | VR_PARAMS_MOTION;
    return a->heap != b->heap || a->broadphase != b->broadphase || a->keep_looks != b->keep_looks ? VR_PARAMS_OWNERS : 0;
}
