/* contact_set.c — the bodies that may be in an island's contact step, and
 * the island step's scratch by object id (contact_set.h).
 *
 * An island step once visited every object three times (union-find
 * parents, island marks, the bodies leaving contact), and allocated and
 * filled arrays of the table's size twice: at 10,000 objects, twelve
 * steps a frame, that was 8 % of a frame with a handful of contacts.  Now
 * it visits the touching pairs and this set: every body whose state was
 * applied with contact set (vrContactSet_Note, from vrWorld_ApplyUpdate),
 * kept sorted and pruned at each step, and found again from every object
 * when the world's structure moved (objects made, deleted, started, read
 * from a saved file) or a worker's frame was undone (vrContactSet_Lost).
 *   note, prune, rescan   the set
 *   vrIds_Sort, vrContactSet_*, vrIslandScratch_Reserve
 */
#include <stdlib.h>
#include "contact_set.h"
#include "grow.h"

static int by_id(const void *x, const void *y)
{
    int a = *(const int *)x, b = *(const int *)y;
    return (a > b) - (a < b);
}

void vrIds_Sort(int *ids, int n)
{
    if (n > 1) qsort(ids, (size_t)n, sizeof *ids, by_id);
}

int vrContactSet_Note(vrWorld *w, int id)
{
    if (vrGrow((void **)&w->contact_ids, &w->contact_idcap, w->ncontact_ids + 1, sizeof *w->contact_ids) != 0)
        return -1;
    w->contact_ids[w->ncontact_ids++] = id;
    return 0;
}

void vrContactSet_Lost(vrWorld *w)
{
    w->contact_structure = w->structure - 1;
    w->applied++;
}

/* A resting body leaves the set: no island step or rest test has
 * anything to do with it, and 10,000 cubes at rest on a floor were
 * sorted and visited at every frame end.  An update wakes it, and an
 * update applied with contact set notes it again. */
static int in_contact(const vrWorld *w, int id)
{
    const vrObject *o = id >= 0 && id < w->table.n ? w->table.obj[id] : NULL;
    return o && o->live && o->body.contact && !o->body.resting;
}

static int ascending(const int *ids, int n)
{
    int i;
    for (i = 1; i < n; i++)
        if (ids[i - 1] > ids[i]) return 0;
    return 1;
}

/* every live body in contact, from the whole table */
static int rescan(vrWorld *w)
{
    int i;
    w->ncontact_ids = 0;
    for (i = 0; i < w->table.n; i++)
        if (in_contact(w, i) && vrContactSet_Note(w, i) != 0) return -1;
    w->contact_structure = w->structure;
    return 0;
}

int vrContactSet_Prune(vrWorld *w)
{
    int i, k = 0;
    if (w->contact_structure != w->structure) return rescan(w);
    if (!ascending(w->contact_ids, w->ncontact_ids)) vrIds_Sort(w->contact_ids, w->ncontact_ids);
    for (i = 0; i < w->ncontact_ids; i++) {
        int id = w->contact_ids[i];
        if ((k == 0 || w->contact_ids[k - 1] != id) && in_contact(w, id)) w->contact_ids[k++] = id;
    }
    w->ncontact_ids = k;
    return 0;
}

/* one array of ints by object id, grown to cap, new entries set to fill */
static int grow_ids(int **a, int old, int cap, int fill)
{
    int *m = realloc(*a, (size_t)cap * sizeof *m), i;
    if (!m) return -1;
    for (i = old; i < cap; i++) m[i] = fill;
    *a = m;
    return 0;
}

int vrIslandScratch_Reserve(vrWorld *w)
{
    int need = w->table.n + 1, cap = w->isl_cap ? w->isl_cap : 16;
    if (need <= w->isl_cap) return 0;
    while (cap < need) cap *= 2;
    if (grow_ids(&w->isl_parent, w->isl_cap, cap, 0) != 0 || grow_ids(&w->isl_in, w->isl_cap, cap, 0) != 0
        || grow_ids(&w->isl_slot, w->isl_cap, cap, -1) != 0 || grow_ids(&w->isl_ids, w->isl_cap, cap, 0) != 0)
        return -1;
    w->isl_cap = cap;
    return 0;
}
