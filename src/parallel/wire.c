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
    int i, k;
    w->n = up->n;
    w->m = calloc((size_t)(up->n ? up->n : 1), sizeof *w->m);
    w->partner = calloc((size_t)(up->n ? up->n : 1), sizeof *w->partner);
    w->joint = calloc((size_t)(up->n ? up->n : 1), sizeof *w->joint);
    w->fixed = calloc((size_t)(up->n ? up->n : 1), sizeof *w->fixed);
    w->normal = calloc((size_t)(up->n ? up->n : 1), sizeof *w->normal);
    if (!w->m || !w->partner || !w->joint || !w->fixed || !w->normal) return -1;
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
        m->hit = (int8_t)st->hit;
        m->nsupport = st->nsupport;
        m->nnormal = 3 * st->nsupport;
        m->partner = w->partner[i];
        m->joint = w->joint[i];
        m->fixed = w->fixed[i];
        m->normal = w->normal[i];
        for (k = 0; k < st->nsupport; k++) {
            w->partner[i][k] = st->support[k].partner;
            w->joint[i][k] = st->support[k].joint;
            w->fixed[i][k] = st->support[k].fixed;
            put3(&w->normal[i][3 * k], st->support[k].n);
        }
    }
    return 0;
}

void vrWire_FreeStates(vrWireStates *w)
{
    free(w->m);
    free(w->partner);
    free(w->joint);
    free(w->fixed);
    free(w->normal);
    memset(w, 0, sizeof *w);
}

static int get_state(const vroc_body_state_t *m, int max_id, vrBodyState *st)
{
    int k;
    if (m->id < 0 || m->id >= max_id || m->nsupport < 0 || m->nsupport > VR_MAX_SUPPORTS
        || m->nnormal != 3 * m->nsupport || !isfinite(m->t) || !finite_all(m->x, 3) || !finite_all(m->v, 3)
        || !finite_all(m->L, 3) || !finite_all(m->q, 4) || !finite_all(m->normal, m->nnormal))
        return -1;
    st->id = m->id;
    st->t = m->t;
    st->x = get3(m->x);
    st->v = get3(m->v);
    st->L = get3(m->L);
    st->q = quat_make(m->q[0], m->q[1], m->q[2], m->q[3]);
    st->raw = m->raw != 0;
    st->resting = m->resting != 0;
    st->hit = m->hit != 0;
    st->nsupport = m->nsupport;
    for (k = 0; k < m->nsupport; k++) {
        if (m->partner[k] < 0 || m->partner[k] >= max_id) return -1;
        st->support[k].partner = m->partner[k];
        st->support[k].joint = m->joint[k] != 0;
        st->support[k].fixed = m->fixed[k] != 0;
        st->support[k].n = get3(&m->normal[3 * k]);
    }
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

int vrWire_PutCandidates(vroc_candidates_t *m, const vrCandidates *c)
{
    int i, k, npt = 0;
    for (i = 0; i < c->n; i++) npt += c->c[i].npoints;
    m->n = c->n;
    m->n3 = 3 * c->n;
    m->npt3 = 3 * npt;
    m->body = malloc((size_t)(c->n + 1) * sizeof *m->body);
    m->partner = malloc((size_t)(c->n + 1) * sizeof *m->partner);
    m->npoints = malloc((size_t)(c->n + 1) * sizeof *m->npoints);
    m->normal = malloc((size_t)(m->n3 + 1) * sizeof *m->normal);
    m->velocity = malloc((size_t)(m->n3 + 1) * sizeof *m->velocity);
    m->points = malloc((size_t)(m->npt3 + 1) * sizeof *m->points);
    if (!m->body || !m->partner || !m->npoints || !m->normal || !m->velocity || !m->points) return -1;
    for (i = 0, npt = 0; i < c->n; i++) {
        const vrCandidate *k0 = &c->c[i];
        m->body[i] = k0->body;
        m->partner[i] = k0->partner;
        m->npoints[i] = k0->npoints;
        put3(&m->normal[3 * i], k0->n);
        put3(&m->velocity[3 * i], k0->partner_velocity);
        for (k = 0; k < k0->npoints; k++, npt++) put3(&m->points[3 * npt], k0->point[k]);
    }
    return 0;
}

void vrWire_FreeCandidates(vroc_candidates_t *m)
{
    free(m->body);
    free(m->partner);
    free(m->npoints);
    free(m->normal);
    free(m->velocity);
    free(m->points);
}

int vrWire_GetCandidates(const vroc_candidates_t *m, int max_id, vrCandidates *out)
{
    int i, k, npt = 0, old = out->n;
    if (m->n < 0 || m->n3 != 3 * m->n || !finite_all(m->normal, m->n3) || !finite_all(m->velocity, m->n3)
        || !finite_all(m->points, m->npt3))
        return -1;
    for (i = 0; i < m->n; i++) {
        vrCandidate *c;
        if (m->body[i] < 0 || m->body[i] >= max_id || m->partner[i] < 0 || m->partner[i] >= max_id
            || m->npoints[i] < 1 || m->npoints[i] > VR_REGION_MAX || 3 * (npt + m->npoints[i]) > m->npt3
            || !(c = vrCandidates_Add(out))) {
            out->n = old;
            return -1;
        }
        c->body = m->body[i];
        c->partner = m->partner[i];
        c->n = get3(&m->normal[3 * i]);
        c->partner_velocity = get3(&m->velocity[3 * i]);
        c->npoints = m->npoints[i];
        for (k = 0; k < c->npoints; k++, npt++) c->point[k] = get3(&m->points[3 * npt]);
    }
    if (3 * npt != m->npt3) {
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
    return 0;    /* ranges are checked when the object is built */
}

void vrWire_PutParams(vroc_params_t *m, const vrParams *p)
{
    m->d = p->d;
    put3(m->accel, p->flight.accel);
    m->max_linear = p->flight.max_linear;
    m->max_angular = p->flight.max_angular;
    m->heap = (int8_t)p->use_heap;
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
    return 0;
}

void vrWire_PutGrid(vroc_grid_t *m, const vrGrid *g)
{
    m->t0 = g->t0;
    m->T = g->T;
    m->h = g->h;
    m->n = g->n;
}

int vrWire_GetGrid(const vroc_grid_t *m, vrGrid *g)
{
    if (!isfinite(m->t0) || !isfinite(m->T) || !isfinite(m->h) || m->n < 0 || m->T < m->t0) return -1;
    g->t0 = m->t0;
    g->T = m->T;
    g->h = m->h;
    g->n = (long)m->n;
    return 0;
}
