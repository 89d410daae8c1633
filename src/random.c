/* random.c — `random N` and `room = s` (SPEC 1.2): the thesis's table 5.6
 * environment, drawn from the world's seeded stream (splitmix.h) so that a
 * seed always gives the same scene and benchmarks mean something.  It
 * builds the scene through the public calls, as a user would.
 *
 *   make_room      six static walls around the interior
 *   free_spot      is a bounding sphere clear of the objects placed so far?
 *   add_one        the next sphere or cube: position, rotation, velocities
 */
#include <string.h>
#include "world_state.h"

#define SPHERE_RADIUS 0.2
#define CUBE_HALF 0.15
#define MAX_TRIES 1000000
#define WALL 0.5            /* wall thickness */

static double uniform(vrWorld *w) { return vrSplitmix_Uniform(&w->rng); }

/* uniform in the ball of radius r, by rejection from the cube */
static vec3 in_ball(vrWorld *w, double r)
{
    for (;;) {
        vec3 p;
        p.x = 2 * uniform(w) - 1;
        p.y = 2 * uniform(w) - 1;
        p.z = 2 * uniform(w) - 1;
        if (vec3_len2(p) <= 1) return vec3_scale(p, r);
    }
}

/* uniform rotation (Shoemake 1992) */
static quat any_rotation(vrWorld *w)
{
    double u1 = uniform(w), u2 = 2 * VR_PI * uniform(w), u3 = 2 * VR_PI * uniform(w);
    double a = sqrt(1 - u1), b = sqrt(u1);
    return quat_make(b * cos(u3), a * sin(u2), a * cos(u2), b * sin(u3));
}

static int is_wall(const char *name)
{
    return strncmp(name, "wall", 4) == 0 && name[4] >= '0' && name[4] <= '5' && name[5] == 0;
}

static int add_box(vrWorld *w, const char *name, vec3 half, vec3 at, char *err, size_t n)
{
    vrObjectId id;
    vrObjectDef d;
    if (vrWorld_CreateObject(w, name, VR_CUBE, &id, err, n) != 0) return -1;
    d = vrObjectDef_Default(VR_CUBE);
    d.size[0] = half.x; d.size[1] = half.y; d.size[2] = half.z;
    d.translate[0] = at.x; d.translate[1] = at.y; d.translate[2] = at.z;
    d.mass = -1;
    d.mass_set = 1;
    d.real = 1;
    d.elasticity = w->s.default_elasticity;   /* SPEC 7: the walls take both defaults */
    d.friction = w->s.default_friction;
    d.color[0] = d.color[1] = d.color[2] = 160;
    return vrWorld_SetObjectDef(w, id, &d, err, n);
}

/* six static walls, WALL thick, around the interior [-s/2, s/2]^2 x [0, s] */
static int make_room(vrWorld *w, double s, char *err, size_t n)
{
    double h = s / 2, o = h + WALL / 2, big = h + WALL, t = WALL / 2;
    return add_box(w, "wall0", vec3_make(big, big, t), vec3_make(0, 0, -t), err, n)
        || add_box(w, "wall1", vec3_make(big, big, t), vec3_make(0, 0, s + t), err, n)
        || add_box(w, "wall2", vec3_make(t, big, big), vec3_make(-o, 0, h), err, n)
        || add_box(w, "wall3", vec3_make(t, big, big), vec3_make(o, 0, h), err, n)
        || add_box(w, "wall4", vec3_make(big, t, big), vec3_make(0, -o, h), err, n)
        || add_box(w, "wall5", vec3_make(big, t, big), vec3_make(0, o, h), err, n) ? -1 : 0;
}

/* is a bounding sphere at c of radius r at least gap away from every object
 * placed so far (room walls: from their inner faces)? */
static int free_spot(vrWorld *w, vec3 c, double r, double gap)
{
    int i;
    vrObjectState st;
    for (i = 0; i < w->table.n; i++) {
        vrObject *o = w->table.obj[i];
        if (!o || is_wall(o->name) || vrWorld_GetObjectState(w, i, &st) != 0) continue;
        if (vec3_dist(c, vec3_make(st.position[0], st.position[1], st.position[2])) < r + o->body.r_out + gap)
            return 0;
    }
    return 1;
}

static int draw_position(vrWorld *w, double r, vec3 *c)
{
    double s = w->s.room > 0 ? w->s.room : 10.0, gap = 2 * w->s.collision_dist;
    double lo = w->s.room > 0 ? r + gap : 0, hi = s - lo;
    long tries;
    for (tries = 0; tries < MAX_TRIES; tries++) {
        c->x = -s / 2 + lo + (hi - lo) * uniform(w);
        c->y = -s / 2 + lo + (hi - lo) * uniform(w);
        c->z = lo + (hi - lo) * uniform(w);
        if (free_spot(w, *c, r, gap)) return 0;
    }
    return -1;
}

static int add_one(vrWorld *w, char *err, size_t n)
{
    int k = w->random_next++, sphere = k % 2 == 0;
    double r = sphere ? SPHERE_RADIUS : CUBE_HALF * sqrt(3.0);
    char name[32];
    vrObjectId id;
    vrObjectDef d;
    vec3 c, v, om;
    quat q;
    snprintf(name, sizeof name, "r%d", k);
    if (draw_position(w, r, &c) != 0) {
        if (err && n) snprintf(err, n, "random: no free place for %s after %d tries", name, MAX_TRIES);
        return -1;
    }
    q = any_rotation(w);
    v = in_ball(w, 4.0);
    om = in_ball(w, 2.0);
    if (vrWorld_CreateObject(w, name, sphere ? VR_SPHERE : VR_CUBE, &id, err, n) != 0) return -1;
    d = vrObjectDef_Default(sphere ? VR_SPHERE : VR_CUBE);
    d.radius = SPHERE_RADIUS;
    d.size[0] = d.size[1] = d.size[2] = CUBE_HALF;
    d.mass = 1;
    d.mass_set = 1;
    d.elasticity = w->s.default_elasticity;    /* SPEC 7: 1 and 0 unless set before */
    d.friction = w->s.default_friction;
    d.translate[0] = c.x; d.translate[1] = c.y; d.translate[2] = c.z;
    d.linear_vel[0] = v.x; d.linear_vel[1] = v.y; d.linear_vel[2] = v.z;
    d.angular_vel[0] = om.x; d.angular_vel[1] = om.y; d.angular_vel[2] = om.z;
    {
        double sh = sqrt(q.x * q.x + q.y * q.y + q.z * q.z);
        d.rotate_set = sh > 0;
        d.rotate_angle = 2 * atan2(sh, q.w);
        d.rotate_axis[0] = sh > 0 ? q.x / sh : 0;
        d.rotate_axis[1] = sh > 0 ? q.y / sh : 0;
        d.rotate_axis[2] = sh > 0 ? q.z / sh : 1;
    }
    d.color[0] = sphere ? 230 : 60;
    d.color[1] = sphere ? 120 : 140;
    d.color[2] = sphere ? 40 : 230;
    return vrWorld_SetObjectDef(w, id, &d, err, n);
}

int vrWorld_AddRandom(vrWorld *w, int n, char *err, size_t errlen)
{
    int i;
    if (n < 0) {
        if (err && errlen) snprintf(err, errlen, "random: N must be >= 0");
        return -1;
    }
    if (w->s.room > 0 && vrWorld_FindObject(w, "wall0") == VR_NO_OBJECT && make_room(w, w->s.room, err, errlen) != 0)
        return -1;
    for (i = 0; i < n; i++)
        if (add_one(w, err, errlen) != 0) return -1;
    return 0;
}
