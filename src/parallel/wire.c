/* wire.c — conversions between the library's structures and LCM messages. */
#include <stdlib.h>
#include <string.h>
#include "grow.h"
#include "wire.h"

static int finite_all(const double *v, int n)
{
    int i;
    for (i = 0; i < n; i++)
        if (!isfinite(v[i])) return 0;
    return 1;
}

static void put3(double *d, vec3 v) { d[0] = v.x; d[1] = v.y; d[2] = v.z; }
static vec3 get3(const double *d) { return vec3_make(d[0], d[1], d[2]); }

int vrWire_PutStates(vrWireStates *w, const vrUpdate *up)
{
    int i;
    w->n = up->n;
    w->m = calloc((size_t)(up->n ? up->n : 1), sizeof *w->m);
    if (!w->m) return -1;
    for (i = 0; i < up->n; i++) {
        const vrBodyState *st = &up->body[i];
        vroc_body_state_t *m = &w->m[i];
        m->id = st->id;
        m->t = st->t;
        put3(m->x, st->x);
        put3(m->v, st->v);
        put3(m->L, st->L);
        m->q[0] = st->q.w; m->q[1] = st->q.x; m->q[2] = st->q.y; m->q[3] = st->q.z;
        m->raw = (int8_t)st->raw;
        m->resting = (int8_t)st->resting;
        /* bit 1: clamped, bit 2: kinematic (held by the hand), no new field on the wire */
        m->hit = (int8_t)(st->hit | st->clamped << 1 | st->kinematic << 2);
        m->contact = (int8_t)st->contact;
        m->island = st->island;
    }
    return 0;
}

void vrWire_FreeStates(vrWireStates *w)
{
    free(w->m);
    memset(w, 0, sizeof *w);
}

static int get_state(const vroc_body_state_t *m, int max_id, vrBodyState *st)
{
    if (m->id < 0 || m->id >= max_id || m->island < -1 || m->island >= max_id || !isfinite(m->t)
        || !finite_all(m->x, 3) || !finite_all(m->v, 3) || !finite_all(m->L, 3) || !finite_all(m->q, 4))
        return -1;
    st->id = m->id;
    st->t = m->t;
    st->x = get3(m->x);
    st->v = get3(m->v);
    st->L = get3(m->L);
    st->q = quat_make(m->q[0], m->q[1], m->q[2], m->q[3]);
    st->raw = m->raw != 0;
    st->resting = m->resting != 0;
    st->hit = (m->hit & 1) != 0;
    st->clamped = (m->hit & 2) != 0;
    st->kinematic = (m->hit & 4) != 0;
    st->contact = m->contact != 0;
    st->island = m->island;
    return 0;
}

int vrWire_GetStates(const vroc_body_state_t *m, int n, int max_id, vrUpdate *up)
{
    int i, old = up->n;
    for (i = 0; i < n; i++) {
        vrBodyState st;
        if (get_state(&m[i], max_id, &st) != 0) {
            up->n = old;
            return -1;
        }
        if (vrGrow((void **)&up->body, &up->cap, up->n + 1, sizeof *up->body) != 0) {
            up->n = old;
            return -1;
        }
        up->body[up->n++] = st;
    }
    return 0;
}

int vrWire_PutTouches(vroc_candidates_t *m, const vrTouches *c)
{
    int i, k, npt = 0;
    for (i = 0; i < c->n; i++) npt += c->t[i].npoints;
    m->n = c->n;
    m->n3 = 3 * c->n;
    m->npt = npt;
    m->npt3 = 3 * npt;
    m->a = malloc((size_t)(c->n + 1) * sizeof *m->a);
    m->b = malloc((size_t)(c->n + 1) * sizeof *m->b);
    m->npoints = malloc((size_t)(c->n + 1) * sizeof *m->npoints);
    m->dist = malloc((size_t)(c->n + 1) * sizeof *m->dist);
    m->leaving = malloc((size_t)(c->n + 1) * sizeof *m->leaving);
    m->normal = malloc((size_t)(m->n3 + 1) * sizeof *m->normal);
    m->gaps = malloc((size_t)(m->npt + 1) * sizeof *m->gaps);
    m->points = malloc((size_t)(m->npt3 + 1) * sizeof *m->points);
    if (!m->a || !m->b || !m->npoints || !m->dist || !m->leaving || !m->normal || !m->gaps || !m->points) return -1;
    for (i = 0, npt = 0; i < c->n; i++) {
        const vrTouch *k0 = &c->t[i];
        m->a[i] = k0->a;
        m->b[i] = k0->b;
        m->npoints[i] = k0->npoints;
        m->dist[i] = k0->dist;
        m->leaving[i] = k0->leaving != 0;
        put3(&m->normal[3 * i], k0->n);
        for (k = 0; k < k0->npoints; k++, npt++) {
            put3(&m->points[3 * npt], k0->point[k]);
            m->gaps[npt] = k0->gap[k];
        }
    }
    return 0;
}

void vrWire_FreeTouches(vroc_candidates_t *m)
{
    free(m->a);
    free(m->b);
    free(m->npoints);
    free(m->dist);
    free(m->leaving);
    free(m->normal);
    free(m->gaps);
    free(m->points);
}

int vrWire_GetTouches(const vroc_candidates_t *m, int max_id, vrTouches *out)
{
    int i, k, npt = 0, old = out->n;
    if (m->n < 0 || m->n3 != 3 * m->n || m->npt3 != 3 * m->npt || !finite_all(m->normal, m->n3)
        || !finite_all(m->dist, m->n) || !finite_all(m->gaps, m->npt) || !finite_all(m->points, m->npt3))
        return -1;
    for (i = 0; i < m->n; i++) {
        vrTouch *c;
        if (m->a[i] < 0 || m->a[i] >= max_id || m->b[i] <= m->a[i] || m->b[i] >= max_id
            || m->npoints[i] < 1 || m->npoints[i] > VR_TOUCH_POINTS || npt + m->npoints[i] > m->npt
            || !(c = vrTouches_Add(out))) {
            out->n = old;
            return -1;
        }
        c->a = m->a[i];
        c->b = m->b[i];
        c->n = get3(&m->normal[3 * i]);
        c->dist = m->dist[i];
        c->leaving = m->leaving[i] != 0;
        c->npoints = m->npoints[i];
        for (k = 0; k < c->npoints; k++, npt++) {
            c->point[k] = get3(&m->points[3 * npt]);
            c->gap[k] = m->gaps[npt];
        }
    }
    if (npt != m->npt) {
        out->n = old;
        return -1;
    }
    return 0;
}

void vrWire_PutDef(vroc_body_def_t *m, int id, const vrObjectDef *d, char *off_text)
{
    static char none[] = "";
    memset(m, 0, sizeof *m);
    m->id = id;
    m->type = (int8_t)d->type;
    m->radius = d->radius;
    m->ures = d->ures;
    m->vres = d->vres;
    memcpy(m->size, d->size, sizeof m->size);
    m->exp1 = d->exp1;
    m->exp2 = d->exp2;
    m->a[0] = d->a1; m->a[1] = d->a2; m->a[2] = d->a3;
    m->mass = d->mass;
    m->mass_set = (int8_t)d->mass_set;
    m->volume = d->volume;
    m->elasticity = d->elasticity;
    m->friction = d->friction;
    m->off = off_text ? off_text : none;
}

int vrWire_GetDef(const vroc_body_def_t *m, vrObjectDef *d)
{
    if (m->type < VR_SPHERE || m->type > VR_POLYHEDRON) return -1;
    *d = vrObjectDef_Default((vrObjectType)m->type);
    d->radius = m->radius;
    d->ures = m->ures;
    d->vres = m->vres;
    memcpy(d->size, m->size, sizeof d->size);
    d->exp1 = m->exp1;
    d->exp2 = m->exp2;
    d->a1 = m->a[0]; d->a2 = m->a[1]; d->a3 = m->a[2];
    d->mass = m->mass;
    d->mass_set = m->mass_set != 0;
    d->volume = m->volume;
    d->elasticity = m->elasticity;
    d->friction = m->friction;
    return 0;    /* ranges are checked when the object is built */
}

void vrWire_PutParams(vroc_params_t *m, const vrParams *p)
{
    m->d = p->d;
    put3(m->accel, p->flight.accel);
    m->max_linear = p->flight.max_linear;
    m->max_angular = p->flight.max_angular;
    m->heap = (int8_t)p->use_heap;
    m->tree = (int8_t)p->use_tree;
    m->keep = (int8_t)p->keep_looks;
}

int vrWire_GetParams(const vroc_params_t *m, vrParams *p)
{
    if (!(m->d > 0) || !finite_all(m->accel, 3) || !(m->max_linear > 0) || !(m->max_angular > 0)
        || !isfinite(m->d) || !isfinite(m->max_linear) || !isfinite(m->max_angular))
        return -1;
    p->d = m->d;
    p->flight.accel = get3(m->accel);
    p->flight.max_linear = m->max_linear;
    p->flight.max_angular = m->max_angular;
    p->use_heap = m->heap != 0;
    p->use_tree = m->tree != 0;
    p->keep_looks = m->keep != 0;
    return 0;
}

void vrWire_PutGrid(vroc_grid_t *m, const vrGrid *g)
{
    m->t0 = g->t0;
    m->T = g->T;
    m->h = g->h;
    m->n = g->n;
    m->frame_T = g->frame_T;
    m->a = g->a;
    m->k0 = g->k0;
}

/* a grid of more steps than a frame may take (VR_FRAME_STEPS_HARD_MAX)
 * comes from no coordinator: a fuzzed frame_start with a huge one kept a
 * worker looking ahead for minutes (make fuzz) */
int vrWire_GetGrid(const vroc_grid_t *m, vrGrid *g)
{
    if (!isfinite(m->t0) || !isfinite(m->T) || !isfinite(m->h) || m->n < 0 || m->n > (int64_t)VR_FRAME_STEPS_HARD_MAX
        || m->T < m->t0 || !(m->frame_T >= m->T) || !isfinite(m->frame_T) || !(m->a <= m->t0) || !isfinite(m->a)
        || m->k0 < 0 || m->k0 > (int64_t)VR_FRAME_STEPS_HARD_MAX)
        return -1;
    g->t0 = m->t0;
    g->T = m->T;
    g->h = m->h;
    g->n = (long)m->n;
    g->frame_T = m->frame_T;
    g->a = m->a;
    g->k0 = (long)m->k0;
    return 0;
}
