/* owners.c — the owners of the pairs, seen from the coordinator.
 *
 * Serial VROC is one owner (owner.h) holding every pair, in this process:
 * "send" is a function call (ARCHITECTURE "the loop, once").  With gps > 0
 * the workers own them instead (parallel/sgp.c); both answer through the
 * same vrOwnerSet, so the frame loop is one loop.
 *
 *   retire_owner       the serial owner goes; its counts stay in the stats
 *   make_serial_owner  one owner of every pair, settled from the poses at t (lazy records, SPEC 10)
 *   deliver            the serial owner hears of the states changed since
 *   serial_*           the serial owner set's operations
 */
#include <stdlib.h>
#include "grow.h"
#include "config.h"
#include "owners.h"
#include "rest.h"
#include "contact_set.h"
#include "parallel/sgp.h"

static void retire_owner(vrWorld *w)
{
    vrOwnerStats os;
    if (!w->owner) return;
    vrOwner_Stats(w->owner, &os);
    w->retired.checks += os.checks;
    w->retired.heap_pops += os.heap_pops;
    w->retired.response.solves += os.response.solves;
    w->retired.response.refactors += os.response.refactors;
    w->retired.response.factors += os.response.factors;
    vrOwner_Free(w->owner);
    w->owner = NULL;
}

/* pairs settle from the poses at t unless a body of theirs changed since
 * the owners last heard */
static int make_serial_owner(vrWorld *w)
{
    vrParams p = vrSettings_Params(&w->s);
    unsigned char *pending;
    int i, rc;
    w->owner = vrOwner_Create();
    if (!w->owner) return -1;
    vrOwner_SetLazy(w->owner, 1);
    vrOwner_SetParams(w->owner, &p);
    for (i = 0; i < w->table.n; i++)
        if (w->table.obj[i] && w->table.obj[i]->live && vrOwner_HoldBody(w->owner, i, &w->table.obj[i]->body) != 0)
            return -1;
    if (!(pending = vrTable_PendingMarks(&w->table, &w->pending))) return -1;
    rc = vrOwner_MakePairsAt(w->owner, w->t, pending);   /* the others as their boxes meet (SPEC 10) */
    free(pending);
    return rc;
}

/* every dynamic–dynamic and dynamic–static pair of a new object (SPEC 3.3:
 * static–static pairs are never made), to be evaluated at the next span */
int vrOwners_AddObject(vrWorld *w, int id)
{
    return w->owner ? vrOwner_AddBody(w->owner, id, &w->table.obj[id]->body) : 0;
}

void vrOwners_Renew(vrWorld *w)
{
    int warm = w->warm.structure == w->structure;
    w->structure++;
    if (warm) w->warm.structure = w->structure;
}

int vrOwners_Choose(vrWorld *w, char *err, size_t n)
{
    if (w->s.gps > 0) {
        if (w->owner) {
            retire_owner(w);
            vrOwners_Renew(w);
        }
        return vrSgp_Sync(w, err, n);
    }
    if (w->sgp) vrSgp_Retire(w);
    if (!w->owner && make_serial_owner(w) != 0) return vrGeom_Fail(err, n, "out of memory");
    return 0;
}

void vrOwners_Retire(vrWorld *w)
{
    retire_owner(w);
    if (w->sgp) vrSgp_Retire(w);
}

int vrWorld_ApplyUpdate(vrWorld *w, vrUpdate *up)
{
    vrFlight f = vrSettings_Flight(&w->s);
    int i;
    if (up->n == 0) return 0;
    w->applied++;
    if (vrRest_WakeDependents(w, up, up->body[0].t) != 0) return -1;
    for (i = 0; i < up->n; i++) {
        vrBody *b = &w->table.obj[up->body[i].id]->body;
        vrRest_KeepFramePose(w, w->table.obj[up->body[i].id]);   /* before its anchor moves */
        w->clamps += vrBody_CapReached(b, w->t, up->body[i].t);   /* its flight met the cap this frame */
        w->clamps += vrBody_Apply(b, &up->body[i], &f);
        if (up->body[i].contact && vrContactSet_Note(w, up->body[i].id) != 0) return -1;
    }
    return vrUpdate_Merge(&w->pending, up, w->table.n);
}

/* ---- the serial owner set ------------------------------------------------------------ */

static int note_changed(vrWorld *w, int id)
{
    if (vrGrow((void **)&w->changed, &w->changedcap, w->nchanged + 1, sizeof *w->changed) != 0) return -1;
    w->changed[w->nchanged++] = id;
    return 0;
}

static int deliver(vrWorld *w)
{
    int i;
    w->nchanged = 0;
    for (i = 0; i < w->pending.n; i++)
        if (note_changed(w, w->pending.body[i].id) != 0) return -1;
    vrOwner_BodiesChanged(w->owner, w->changed, w->nchanged);
    w->pending.n = 0;
    return 0;
}

static int serial_first_event(vrWorld *w, const vrGrid *g, int allow, vrEvent *ev, char *err, size_t n)
{
    int r;
    if (deliver(w) != 0) return vrGeom_Fail(err, n, "out of memory");
    r = vrOwner_FirstEvent(w->owner, g, allow, ev);
    return r < 0 ? vrGeom_Fail(err, n, "out of memory") : r;
}

static int serial_respond(vrWorld *w, const vrEvent *ev, vrUpdate *up, char *err, size_t n)
{
    vrOwner_AdvanceTo(w->owner, ev);
    if (vrOwner_Respond(w->owner, ev, up) != 0) return vrGeom_Fail(err, n, "collision response: the linear solve failed");
    return 0;
}

static void serial_end_frame(vrWorld *w, double T) { vrOwner_Advance(w->owner, T); }

static int serial_overlapping(vrWorld *w, double tol, const int *ids, int nids, int (*out)[2], int max, char *err,
                              size_t n)
{
    int k;
    if (deliver(w) != 0) return vrGeom_Fail(err, n, "out of memory");
    k = vrOwner_Overlapping(w->owner, w->t, tol, ids, nids, out, max);
    return k < 0 ? vrGeom_Fail(err, n, "out of memory") : k;
}

static int serial_touching(vrWorld *w, double t, double h, int a, int b, vrTouches *out, char *err, size_t n)
{
    vrOwner_Advance(w->owner, t);
    if (deliver(w) != 0
        || (h == 0 ? vrOwner_TouchingFrom(w->owner, t, a, b, out) : vrOwner_Touching(w->owner, t, h, out)) != 0)
        return vrGeom_Fail(err, n, "out of memory");
    return 0;
}

static const vrOwnerSet serial_owners = {serial_first_event, serial_respond, serial_end_frame, serial_overlapping,
                                         serial_touching};

const vrOwnerSet *vrOwners_Of(const vrWorld *w) { return w->s.gps > 0 ? &vrSgp_Owners : &serial_owners; }
