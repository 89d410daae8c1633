/* grab_save.c — the hand's grab state in a saved file (SPEC 11: "save
 * keeps grab state"): what is held and its offset, the last object held
 * (reselect), the buttons as dispatched, the flown viewpoint.  A held
 * body's saved anchor holds its motion as a kinematic body (body.h: L is
 * its angular velocity), so the reader marks it kinematic again before
 * the run goes live.  (The hand's samples themselves are the track's.) */
#include "grab.h"
#include "resume.h"
#include "saved.h"
#include "save_line.h"
#include "config.h"

static int untouched(const vrGrab *g)
{
    return g->held < 0 && g->last < 0 && g->buttons == 0 && !g->flying && g->t_done == -INFINITY
        && vec3_len2(g->fly) == 0;
}

static void put3(FILE *out, const char *key, vec3 v)
{
    double a[3] = {v.x, v.y, v.z};
    vrSave_Vector(out, key, a, 3);
}

/* one filtered sample: prefix t, x, q, dx */
static void put_filtered(FILE *out, const char *prefix, const vrHandFiltered *f)
{
    char key[8];
    double q[4] = {f->q.w, f->q.x, f->q.y, f->q.z};
    snprintf(key, sizeof key, "%.3st", prefix);
    vrSave_Number(out, key, f->t);
    snprintf(key, sizeof key, "%.3sx", prefix);
    put3(out, key, f->x);
    snprintf(key, sizeof key, "%.3sq", prefix);
    vrSave_Vector(out, key, q, 4);
    snprintf(key, sizeof key, "%.3sdx", prefix);
    put3(out, key, f->dx);
}

void vrGrab_Save(vrWorld *w, int id, FILE *out)
{
    const vrGrab *g = &w->grab;
    double q[4] = {g->off_q.w, g->off_q.x, g->off_q.y, g->off_q.z};
    (void)id;
    if (untouched(g)) return;
    fputs("state grab", out);
    vrSave_Number(out, "t_done", g->t_done);
    vrSave_Integer(out, "buttons", g->buttons);
    vrSave_Integer(out, "held", g->held);
    vrSave_Integer(out, "last", g->last);
    put3(out, "off_p", g->off_p);
    vrSave_Vector(out, "off_q", q, 4);
    vrSave_Integer(out, "flying", g->flying);
    vrSave_Number(out, "fly_t", g->fly_t);
    put3(out, "fly", g->fly);
    put3(out, "fly_dir", g->fly_dir);
    vrSave_Integer(out, "f_n", g->filter.n);
    put_filtered(out, "f_p", &g->filter.prev);
    put_filtered(out, "f_l", &g->filter.last);
    fputc('\n', out);
}

static int get3(vrSaveLine *l, const char *key, vec3 *v, char *err, size_t n)
{
    double a[3];
    if (vrSaveLine_Numbers(l, key, a, 3, 0, err, n) != 0) return -1;
    *v = vrVec3_Of(a);
    return 0;
}

static int get_filtered(vrSaveLine *l, const char *prefix, vrHandFiltered *f, char *err, size_t n)
{
    char key[8];
    double q[4];
    snprintf(key, sizeof key, "%.3st", prefix);
    if (vrSaveLine_Numbers(l, key, &f->t, 1, 0, err, n) != 0) return -1;
    snprintf(key, sizeof key, "%.3sx", prefix);
    if (get3(l, key, &f->x, err, n) != 0) return -1;
    snprintf(key, sizeof key, "%.3sq", prefix);
    if (vrSaveLine_Numbers(l, key, q, 4, 0, err, n) != 0) return -1;
    f->q = quat_make(q[0], q[1], q[2], q[3]);
    snprintf(key, sizeof key, "%.3sdx", prefix);
    return get3(l, key, &f->dx, err, n);
}

/* the held body goes on as the kinematic body it was (its saved anchor,
 * and any state of it the owners had not heard) */
static int mark_held(vrWorld *w, int id, char *err, size_t n)
{
    vrObject *o = id < w->table.n ? w->table.obj[id] : NULL;
    vrFlight f = vrSettings_Flight(&w->s);
    vrResume *r = vrSave_Resumed(w);
    int i;
    if (!o || !o->saved || (o->def.mass_set && o->def.mass < 0))
        return vrGeom_Fail(err, n, "state grab: held=%d is no saved dynamic object", id);
    if (!r) return vrGeom_Fail(err, n, "out of memory");
    o->saved->anchor.kinematic = 1;
    vrSaved_Place(o, &f);
    for (i = 0; i < r->pending.n; i++)
        if (r->pending.body[i].id == id) r->pending.body[i].kinematic = 1;
    return 0;
}

int vrGrab_Read(vrWorld *w, int id, vrSaveLine *l, char *err, size_t n)
{
    vrGrab g;
    long long buttons, held, last, flying, fn;
    double q[4];
    (void)id;
    vrGrab_Init(&g);
    if (vrSaveLine_Numbers(l, "t_done", &g.t_done, 1, 1, err, n) || vrSaveLine_Integer(l, "buttons", 0, 3, &buttons, err, n)
        || vrSaveLine_Integer(l, "held", -1, w->table.n - 1, &held, err, n)
        || vrSaveLine_Integer(l, "last", -1, w->table.n - 1, &last, err, n) || get3(l, "off_p", &g.off_p, err, n)
        || vrSaveLine_Numbers(l, "off_q", q, 4, 0, err, n) || vrSaveLine_Integer(l, "flying", 0, 1, &flying, err, n)
        || vrSaveLine_Numbers(l, "fly_t", &g.fly_t, 1, 1, err, n) || get3(l, "fly", &g.fly, err, n)
        || get3(l, "fly_dir", &g.fly_dir, err, n) || vrSaveLine_Integer(l, "f_n", 0, 2, &fn, err, n)
        || get_filtered(l, "f_p", &g.filter.prev, err, n) || get_filtered(l, "f_l", &g.filter.last, err, n))
        return -1;
    g.filter.n = (int)fn;
    g.off_q = quat_make(q[0], q[1], q[2], q[3]);
    if (fabs(quat_norm(g.off_q) - 1) > 1e-6) return vrGeom_Fail(err, n, "state grab: off_q must be a unit quaternion");
    g.buttons = (unsigned)buttons, g.held = (int)held, g.last = (int)last, g.flying = (int)flying;
    if (g.held >= 0 && mark_held(w, g.held, err, n) != 0) return -1;
    w->grab = g;
    return 0;
}
