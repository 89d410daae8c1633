/* save_world.c — the world-wide sections of a saved file (save_sections.h):
 *   clock     simulation time, frame count, the frame grid's base, the
 *             last instant's responses, settings waiting for the next frame
 *   counters  the statistics that count (SPEC 1.3), continued from here
 *   random    `random`'s numbering and its stream's state
 *   gap       an id that a deleted object left
 *   live      the end: the objects go live as the saving run's are
 */
#include <math.h>
#include "grow.h"
#include "save_sections.h"
#include "start.h"

void vrSave_WriteClock(vrWorld *w, int id, FILE *out)
{
    (void)id;
    fputs("state clock", out);
    vrSave_Number(out, "t", w->t);
    vrSave_Integer(out, "frames", w->frames);
    vrSave_Number(out, "t_base", w->t_base);
    vrSave_Integer(out, "frames_base", w->frames_base);
    vrSave_Integer(out, "instant", w->instant);
    vrSave_Number(out, "instant_t", w->instant_t);
    vrSave_Integer(out, "settings_due", w->params_dirty);
    fputc('\n', out);
}

int vrSave_ReadClock(vrWorld *w, int id, vrSaveLine *l, char *err, size_t n)
{
    double t, t_base, instant_t;
    long long frames, frames_base, instant, due;
    (void)id;
    if (vrSaveLine_Numbers(l, "t", &t, 1, 0, err, n) || vrSaveLine_Integer(l, "frames", 0, 1000000000000LL, &frames, err, n)
        || vrSaveLine_Numbers(l, "t_base", &t_base, 1, 0, err, n)
        || vrSaveLine_Integer(l, "frames_base", 0, frames, &frames_base, err, n)
        || vrSaveLine_Integer(l, "instant", 0, 1000000000, &instant, err, n)
        || vrSaveLine_Numbers(l, "instant_t", &instant_t, 1, 1, err, n)
        || vrSaveLine_Integer(l, "settings_due", 0, 3, &due, err, n))
        return -1;
    if (t < 0 || t_base < 0 || t_base > t) {
        snprintf(err, n, "state clock: needs 0 <= t_base <= t");
        return -1;
    }
    if (!vrSave_Resumed(w)) {          /* the owners' unheard states: none unless lines follow */
        snprintf(err, n, "out of memory");
        return -1;
    }
    w->t = t, w->frames = (long)frames, w->t_base = t_base, w->frames_base = (long)frames_base;
    w->instant = (int)instant, w->instant_t = instant_t;
    w->params_dirty = (int)due;   /* what the settings above made due is the saved run's, no more */
    return 0;
}

/* the counters, by key, where they live in the world */
typedef struct Counter { const char *key; size_t offset; int is_long; } Counter;
static const Counter counters[] = {
    {"collisions", offsetof(vrWorld, collisions), 0},
    {"island_steps", offsetof(vrWorld, island_steps), 0},
    {"island_contacts", offsetof(vrWorld, island_contacts), 0},
    {"checks", offsetof(vrWorld, retired.checks), 0},
    {"heap_pops", offsetof(vrWorld, retired.heap_pops), 0},
    {"klu_solves", offsetof(vrWorld, retired.response.solves), 0},
    {"klu_refactors", offsetof(vrWorld, retired.response.refactors), 0},
    {"klu_factors", offsetof(vrWorld, retired.response.factors), 0},
    {"subframes", offsetof(vrWorld, subframes), 1},
    {"clamps", offsetof(vrWorld, clamps), 0},
};
#define NCOUNTERS ((int)(sizeof counters / sizeof counters[0]))

static long long counter_get(const vrWorld *w, const Counter *c)
{
    const char *p = (const char *)w + c->offset;
    return c->is_long ? *(const long *)p : *(const long long *)p;
}

void vrSave_WriteCounters(vrWorld *w, int id, FILE *out)
{
    int k;
    (void)id;
    fputs("state counters", out);
    for (k = 0; k < NCOUNTERS; k++) vrSave_Integer(out, counters[k].key, counter_get(w, &counters[k]));
    fputc('\n', out);
}

int vrSave_ReadCounters(vrWorld *w, int id, vrSaveLine *l, char *err, size_t n)
{
    long long v[NCOUNTERS];
    int k;
    (void)id;
    for (k = 0; k < NCOUNTERS; k++)
        if (vrSaveLine_Integer(l, counters[k].key, 0, counters[k].is_long ? 2147483647LL : 9000000000000000000LL, &v[k],
                               err, n) != 0)
            return -1;
    for (k = 0; k < NCOUNTERS; k++) {
        char *p = (char *)w + counters[k].offset;
        if (counters[k].is_long) *(long *)p = (long)v[k];
        else *(long long *)p = v[k];
    }
    return 0;
}

void vrSave_WriteRandom(vrWorld *w, int id, FILE *out)
{
    (void)id;
    fprintf(out, "state random next=%d stream=%llu\n", w->random_next, w->rng.state);
}

int vrSave_ReadRandom(vrWorld *w, int id, vrSaveLine *l, char *err, size_t n)
{
    long long next;
    unsigned long long stream;
    (void)id;
    if (vrSaveLine_Integer(l, "next", 0, 2000000000, &next, err, n) || vrSaveLine_U64(l, "stream", &stream, err, n))
        return -1;
    w->random_next = (int)next;
    w->rng.state = stream;
    return 0;
}

int vrSave_ReadGap(vrWorld *w, int id, vrSaveLine *l, char *err, size_t n)
{
    vrTable *t = &w->table;
    (void)id, (void)l;
    if (vrGrow((void **)&t->obj, &t->cap, t->n + 1, sizeof *t->obj) != 0) { /* NOLINT(bugprone-sizeof-expression): an array of pointers */
        snprintf(err, n, "out of memory");
        return -1;
    }
    t->obj[t->n++] = NULL;
    return 0;
}

void vrSave_WriteLive(vrWorld *w, int id, FILE *out)
{
    (void)w, (void)id;
    fputs("state live\n", out);
}

/* An edit, a deletion, `start`'s rest test act on live objects: the
 * saving run's are, so the reader's must be before what follows. */
int vrSave_ReadLive(vrWorld *w, int id, vrSaveLine *l, char *err, size_t n)
{
    (void)id, (void)l;
    if (vrWorld_GoLive(w, err, n) != 0) return -1;
    w->started = 1;                    /* no more state lines: this run is the saved one now */
    return 0;
}
