/* start.c — vrWorld_Start: the world made ready for a frame.
 *
 *   apply_params     changed settings reach the owners; bodies re-anchored
 *   build_all, ready_all   every object built (each failure named), then placed
 *   report_overlaps  SPEC 1.4: added or moved objects must not interpenetrate
 */
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include "grow.h"
#include "build.h"
#include "config.h"
#include "owners.h"
#include "resume.h"
#include "start.h"

#define MAX_REPORTED_OVERLAPS 8
#define MAX_REPORTED_BUILDS 8

int vrWorld_ListDynamic(vrWorld *w)
{
    int i;
    w->ndyn = 0;
    w->ndyn_slot = 0;
    if (vrGrow((void **)&w->dyn_slot, &w->dyn_slotcap, w->table.n, sizeof *w->dyn_slot) != 0) return -1;
    w->ndyn_slot = w->table.n;
    for (i = 0; i < w->table.n; i++) {
        vrObject *o = w->table.obj[i];
        w->dyn_slot[i] = -1;
        if (!o || !o->live || o->body.is_static) continue;
        if (vrGrow((void **)&w->dyn, &w->dyncap, w->ndyn + 1, sizeof *w->dyn) != 0) return -1; /* NOLINT(bugprone-sizeof-expression): an array of pointers */
        w->dyn_slot[i] = w->ndyn;
        w->dyn[w->ndyn++] = &o->body;
    }
    return 0;
}

/* the objects made since the last start become live, their states
 * pending for the owners (an edited one's already is: not searched for
 * each of 10,000 new ones) */
int vrWorld_MakeLive(vrWorld *w, char *err, size_t n)
{
    unsigned char *held = calloc((size_t)w->table.n + 1, 1);
    int i;
    if (!held) return vrGeom_Fail(err, n, "out of memory");
    for (i = 0; i < w->pending.n; i++)
        if (w->pending.body[i].id >= 0 && w->pending.body[i].id < w->table.n) held[w->pending.body[i].id] = 1;
    for (i = 0; i < w->table.n; i++) {
        vrObject *o = w->table.obj[i];
        if (!o || o->live) continue;
        o->live = 1;
        if (!(held[i] ? vrUpdate_Body(&w->pending, &o->body, w->t) : vrUpdate_Append(&w->pending, &o->body, w->t))) {
            free(held);
            return vrGeom_Fail(err, n, "out of memory");
        }
        if (vrOwners_AddObject(w, i) != 0) {
            free(held);
            return vrGeom_Fail(err, n, "out of memory");
        }
        w->structure++;
        o->overlap_owed = 1;
        w->table.unready = 1;
    }
    free(held);
    return vrWorld_ListDynamic(w) == 0 ? 0 : vrGeom_Fail(err, n, "out of memory");
}

/* re-anchor every dynamic body after a change of settings */
static int apply_params(vrWorld *w)
{
    vrParams p = vrSettings_Params(&w->s);
    int i;
    int motion = w->params_dirty & VR_PARAMS_MOTION;
    if (w->owner) vrOwner_SetParams(w->owner, &p);   /* flags every pair */
    w->update.n = 0;
    for (i = 0; motion && i < w->ndyn; i++)       /* each body once */
        if (!vrUpdate_Append(&w->update, w->dyn[i], w->t)) return -1;
    w->params_dirty = 0;
    if (motion) w->structure++;                      /* workers are made anew with them */
    else vrOwners_Renew(w);                          /* heap, broadphase: the same physics */
    return vrWorld_ApplyUpdate(w, &w->update);
}

/* a list message grown in place: fmt appended to what err holds */
static void append(char *err, size_t n, const char *fmt, ...)
{
    size_t len = strlen(err);
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(err + len, n - len, fmt, ap);
    va_end(ap);
}

/* SPEC 1.4: the pairs of the bodies added or moved since the last start
 * that checked (every body at the first start; none owed: nothing to ask);
 * the other pairs were looked after by the run.  Serial and workers check
 * exactly these, so they agree whatever pairs their owners have flagged. */
static int report_overlaps(vrWorld *w, char *err, size_t n)
{
    int pairs[MAX_REPORTED_OVERLAPS][2], k, i, nids = 0;
    int *ids;
    for (i = 0; i < w->table.n; i++)
        if (w->table.obj[i] && w->table.obj[i]->overlap_owed) break;
    if (i == w->table.n) return 0;
    ids = malloc((size_t)w->table.n * sizeof *ids);
    if (!ids) return vrGeom_Fail(err, n, "out of memory");
    for (i = 0; i < w->table.n; i++)
        if (w->table.obj[i] && w->table.obj[i]->live && w->table.obj[i]->overlap_owed) ids[nids++] = i;
    k = nids ? vrOwners_Of(w)->overlapping(w, VR_START_OVERLAP, ids, nids, pairs, MAX_REPORTED_OVERLAPS, err, n) : 0;
    free(ids);
    if (k < 0) return -1;
    if (k == 0) {
        for (i = 0; i < w->table.n; i++)
            if (w->table.obj[i]) w->table.obj[i]->overlap_owed = 0;
        return 0;
    }
    if (!err || !n) return -1;
    snprintf(err, n, "objects interpenetrate, not starting:");
    for (i = 0; i < k && i < MAX_REPORTED_OVERLAPS; i++)
        append(err, n, "%s %s and %s", i ? ";" : "", w->table.obj[pairs[i][0]]->name, w->table.obj[pairs[i][1]]->name);
    if (k > MAX_REPORTED_OVERLAPS) append(err, n, "; and %d more pairs", k - MAX_REPORTED_OVERLAPS);
    return -1;
}

/* builds what changed, naming every object that cannot be built (two
 * polyhedra without a file: both, not one a try); -1 when any failed */
static int build_all(vrWorld *w, char *err, size_t n)
{
    int i, failed = 0;
    char why[512];
    for (i = 0; i < w->table.n; i++) {
        vrObject *o = w->table.obj[i];
        if (!o || o->built || vrObject_Build(o, why, sizeof why) == 0) continue;
        if (++failed > MAX_REPORTED_BUILDS || !err || !n) continue;
        if (failed == 1) err[0] = '\0';
        append(err, n, "%sobject '%s': %s", failed == 1 ? "" : "; ", o->name, why);
    }
    if (failed > MAX_REPORTED_BUILDS && err && n) append(err, n, "; and %d more objects", failed - MAX_REPORTED_BUILDS);
    return failed ? -1 : 0;
}

/* builds what changed and places the objects not yet in the simulation:
 * none is placed until every one is built, so a start that fails places
 * nothing (and counts no clamp of a placement twice when it is tried
 * again) */
static int ready_all(vrWorld *w, char *err, size_t n)
{
    vrFlight f = vrSettings_Flight(&w->s);
    int i;
    if (build_all(w, err, n) != 0) return -1;
    for (i = 0; i < w->table.n; i++)
        if (w->table.obj[i] && !w->table.obj[i]->live) w->clamps += vrObject_Place(w->table.obj[i], w->t, &f);
    return 0;
}

int vrWorld_GoLive(vrWorld *w, char *err, size_t n)
{
    if (ready_all(w, err, n) != 0 || vrWorld_MakeLive(w, err, n) != 0) return -1;
    return vrSave_Resume(w) == 0 ? 0 : vrGeom_Fail(err, n, "out of memory");
}

int vrWorld_TakeSettings(vrWorld *w, const vrSettings *s, char *err, size_t n)
{
    if (vrSettings_Check(s, err, n) != 0) return -1;
    w->params_dirty |= vrSettings_Changes(&w->s, s);
    if (s->time_step != w->s.time_step) {
        w->t_base = w->t;
        w->frames_base = w->frames;
    }
    if (s->seed != w->s.seed) vrSplitmix_Seed(&w->rng, s->seed);
    w->s = *s;
    return 0;
}

/* SPEC 8: a slider moved in the last frame sets its value here, at the
 * frame boundary, as the same statement typed between frames would; a
 * value the other settings refuse (internal_step too fine for the new
 * time_step) is an error naming the slider, and the knob goes back */
static int take_panel(vrWorld *w, char *err, size_t n)
{
    vrSettings s;
    char why[400];
    if (!vrPanel_TakeSettings(w, &s) || vrWorld_TakeSettings(w, &s, why, sizeof why) == 0) return 0;
    return vrGeom_Fail(err, n, "the tool panel's slider: %s", why);
}

/* Every frame starts here: the passes over the table (build, place, make
 * live, release saved states, check overlaps) only when something gave
 * them work since the last start (table.unready: they were 10 % of a frame
 * of 10,000 flying objects). */
int vrWorld_Start(vrWorld *w, char *err, size_t n)
{
    int unready = w->table.unready || w->resume;
    if (take_panel(w, err, n) != 0) return -1;
    if (unready && vrWorld_GoLive(w, err, n) != 0) return -1;
    if (w->params_dirty && apply_params(w) != 0) return vrGeom_Fail(err, n, "out of memory");
    if (vrOwners_Choose(w, err, n) != 0) return -1;
    if (unready && report_overlaps(w, err, n) != 0) return -1;
    w->table.unready = 0;
    w->started = 1;
    return 0;
}
