/* random.c — `random N` and `room = s` (SPEC 1.2): the thesis's table 5.6
 * environment, drawn from the world's seeded stream (splitmix.h) so that a
 * seed always gives the same scene and benchmarks mean something.  It
 * builds the scene through the public calls, as a user would.
 *
 *   make_room      six static walls around the interior
 *   place, free_spot   the objects placed so far in a grid; is a bounding sphere clear of them?
 *   add_one        the next sphere or cube: position, rotation, velocities
 */
#include <stdlib.h>
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

/* The objects placed so far, by their bounding spheres at the world's time
 * (the walls aside: the draw keeps clear of them), in a hashed grid of
 * cells no smaller than any distance free_spot asks about, so that a draw
 * looks at the few objects in the 27 cells about it, not at all of them
 * (10,000 objects); objects wider than SMALL_R are looked at always.  The
 * answers are the same as a look at every object. */
#define SMALL_R 1.0
typedef struct vrPlaced {
    vec3 *c;
    double *r;
    int *next, n, cap;
    int *head, mask;          /* bucket heads, by hashed cell */
    int *big, nbig;           /* the wide ones */
    double cell;
} vrPlaced;

static unsigned cell_hash(long long x, long long y, long long z)
{
    unsigned long long h = (unsigned long long)x * 73856093ull ^ (unsigned long long)y * 19349663ull
                         ^ (unsigned long long)z * 83492791ull;
    return (unsigned)(h ^ (h >> 29));
}

static long long cell_of(const vrPlaced *p, double x) { return (long long)floor(x / p->cell); }

static void place(vrPlaced *p, vec3 c, double r)
{
    int i = p->n++;
    p->c[i] = c;
    p->r[i] = r;
    if (r > SMALL_R) {
        p->big[p->nbig++] = i;
        return;
    }
    {
        unsigned b = cell_hash(cell_of(p, c.x), cell_of(p, c.y), cell_of(p, c.z)) & (unsigned)p->mask;
        p->next[i] = p->head[b];
        p->head[b] = i;
    }
}

/* object id, built, in the grid (a wall or one without a state: not) */
static void place_object(vrWorld *w, vrPlaced *p, int id)
{
    vrObject *o = w->table.obj[id];
    vrObjectState st;
    if (!o || is_wall(o->name) || vrWorld_GetObjectState(w, id, &st) != 0) return;
    place(p, vec3_make(st.position[0], st.position[1], st.position[2]), o->body.r_out);
}

static void placed_free(vrPlaced *p)
{
    free(p->c);
    free(p->r);
    free(p->next);
    free(p->head);
    free(p->big);
}

/* room for the objects there are and n more, those there are placed */
static int placed_init(vrWorld *w, vrPlaced *p, int n)
{
    int cap = w->table.n + n + 1, nb = 16, i;
    while (nb < 2 * cap) nb *= 2;
    memset(p, 0, sizeof *p);
    p->cap = cap;
    p->mask = nb - 1;
    p->cell = SPHERE_RADIUS + CUBE_HALF * sqrt(3.0) + SMALL_R + 2 * w->s.collision_dist;
    p->c = malloc((size_t)cap * sizeof *p->c);
    p->r = malloc((size_t)cap * sizeof *p->r);
    p->next = malloc((size_t)cap * sizeof *p->next);
    p->big = malloc((size_t)cap * sizeof *p->big);
    p->head = malloc((size_t)nb * sizeof *p->head);
    if (!p->c || !p->r || !p->next || !p->big || !p->head) return placed_free(p), -1;
    for (i = 0; i < nb; i++) p->head[i] = -1;
    for (i = 0; i < w->table.n; i++) place_object(w, p, i);
    return 0;
}

static int clear_of(const vrPlaced *p, int i, vec3 c, double r, double gap)
{
    return !(vec3_dist(c, p->c[i]) < r + p->r[i] + gap);
}

/* is a bounding sphere at c of radius r (at most the cell's reach) at
 * least gap away from every object placed so far (room walls: from their
 * inner faces)? */
static int free_spot(const vrPlaced *p, vec3 c, double r, double gap)
{
    long long x = cell_of(p, c.x), y = cell_of(p, c.y), z = cell_of(p, c.z), dx, dy, dz;
    int i;
    for (i = 0; i < p->nbig; i++)
        if (!clear_of(p, p->big[i], c, r, gap)) return 0;
    for (dx = -1; dx <= 1; dx++)
        for (dy = -1; dy <= 1; dy++)
            for (dz = -1; dz <= 1; dz++)
                for (i = p->head[cell_hash(x + dx, y + dy, z + dz) & (unsigned)p->mask]; i >= 0; i = p->next[i])
                    if (!clear_of(p, i, c, r, gap)) return 0;
    return 1;
}

static int draw_position(vrWorld *w, const vrPlaced *p, double r, vec3 *c)
{
    double s = w->s.room > 0 ? w->s.room : 10.0, gap = 2 * w->s.collision_dist;
    double lo = w->s.room > 0 ? r + gap : 0, hi = s - lo;
    long tries;
    for (tries = 0; tries < MAX_TRIES; tries++) {
        c->x = -s / 2 + lo + (hi - lo) * uniform(w);
        c->y = -s / 2 + lo + (hi - lo) * uniform(w);
        c->z = lo + (hi - lo) * uniform(w);
        if (free_spot(p, *c, r, gap)) return 0;
    }
    return -1;
}

static int add_one(vrWorld *w, vrPlaced *p, char *err, size_t n)
{
    int k = w->random_next++, sphere = k % 2 == 0;
    double r = sphere ? SPHERE_RADIUS : CUBE_HALF * sqrt(3.0);
    char name[32];
    vrObjectId id;
    vrObjectDef d;
    vec3 c, v, om;
    quat q;
    snprintf(name, sizeof name, "r%d", k);
    if (draw_position(w, p, r, &c) != 0) {
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
    if (vrWorld_SetObjectDef(w, id, &d, err, n) != 0) return -1;
    place_object(w, p, id);
    return 0;
}

int vrWorld_AddRandom(vrWorld *w, int n, char *err, size_t errlen)
{
    vrPlaced p;
    int i, rc = 0;
    if (n < 0) {
        if (err && errlen) snprintf(err, errlen, "random: N must be >= 0");
        return -1;
    }
    if (w->s.room > 0 && vrWorld_FindObject(w, "wall0") == VR_NO_OBJECT && make_room(w, w->s.room, err, errlen) != 0)
        return -1;
    if (placed_init(w, &p, n) != 0) {
        if (err && errlen) snprintf(err, errlen, "random: out of memory");
        return -1;
    }
    for (i = 0; i < n && rc == 0; i++) rc = add_one(w, &p, err, errlen);
    placed_free(&p);
    return rc;
}
