/* table.c — the object table: objects by id and by name, their
 * definitions, and the OFF text a polyhedron's definition brings.
 *
 *   valid_name         [A-Za-z_][A-Za-z0-9_.-]*, at most VR_NAME_MAX bytes
 *   room_for_one_more  grows the table so that id t->n is free
 *   off_from_text      a polyhedron from OFF text (a worker gets the text)
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "table.h"
#include "off.h"
#include "config.h"
#include "shape_share.h"

vrObject *vrTable_Get(const vrTable *t, int id)
{
    return id >= 0 && id < t->n ? t->obj[id] : NULL;
}

static int valid_name(const char *s)
{
    size_t i, n = strlen(s);
    if (n == 0 || n > VR_NAME_MAX) return 0;
    for (i = 0; i < n; i++) {
        char c = s[i];
        int alpha = (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || c == '_';
        int digit = c >= '0' && c <= '9';
        if (!(alpha || (i > 0 && (digit || c == '.' || c == '-')))) return 0;
    }
    return 1;
}

/* ---- the name index: 10,000 objects are created and looked up by name
 * in time that does not grow with the count (FNV-1a, linear probing) ---- */

static unsigned name_hash(const char *s)
{
    unsigned h = 2166136261u;
    for (; *s; s++) h = (h ^ (unsigned char)*s) * 16777619u;
    return h;
}

static void index_put(vrTable *t, int id)
{
    unsigned mask = (unsigned)t->indexcap - 1, i = name_hash(t->obj[id]->name) & mask;
    while (t->index[i] >= 0) i = (i + 1) & mask;
    t->index[i] = id;
    t->nindex++;
}

/* made anew at twice the room needed, without the deleted objects' ids;
 * without memory the table has no index (lookups walk the table) */
static void index_remake(vrTable *t)
{
    int cap = 64, i;
    while (cap < 4 * (t->n + 1)) cap *= 2;
    free(t->index);
    t->nindex = 0;
    t->indexcap = 0;
    if (!(t->index = malloc((size_t)cap * sizeof *t->index))) return;
    t->indexcap = cap;
    for (i = 0; i < cap; i++) t->index[i] = -1;
    for (i = 0; i < t->n; i++)
        if (t->obj[i]) index_put(t, i);
}

static void index_add(vrTable *t, int id)
{
    if (2 * (t->nindex + 1) > t->indexcap) index_remake(t);
    else index_put(t, id);
}

int vrTable_Find(const vrTable *t, const char *name)
{
    int i;
    if (t->indexcap) {
        unsigned mask = (unsigned)t->indexcap - 1, k;
        for (k = name_hash(name) & mask; t->index[k] >= 0; k = (k + 1) & mask) {
            const vrObject *o = t->index[k] < t->n ? t->obj[t->index[k]] : NULL;
            if (o && strcmp(o->name, name) == 0) return t->index[k];
        }
        return VR_NO_OBJECT;
    }
    for (i = 0; i < t->n; i++)
        if (t->obj[i] && strcmp(t->obj[i]->name, name) == 0) return i;
    return VR_NO_OBJECT;
}

static int room_for_one_more(vrTable *t, char *err, size_t n)
{
    int cap;
    vrObject **no;
    if (t->n < t->cap) return 0;
    cap = t->cap ? 2 * t->cap : 64;
    no = realloc(t->obj, (size_t)cap * sizeof *no); /* NOLINT(bugprone-sizeof-expression): an array of pointers */
    if (!no) return vrGeom_Fail(err, n, "out of memory");
    t->obj = no;
    t->cap = cap;
    return 0;
}

int vrTable_Add(vrTable *t, const char *name, vrObjectType type, int *id, char *err, size_t n)
{
    vrObject *o;
    if (!valid_name(name))
        return vrGeom_Fail(err, n, "bad object name '%.80s' (letters, digits, _ . -, at most %d bytes)", name, VR_NAME_MAX);
    if (vrTable_Find(t, name) != VR_NO_OBJECT) return vrGeom_Fail(err, n, "object '%s' exists", name);
    if (room_for_one_more(t, err, n) != 0) return -1;
    o = calloc(1, sizeof *o);
    if (!o) return vrGeom_Fail(err, n, "out of memory");
    strcpy(o->name, name);
    o->def = vrObjectDef_Default(type);
    o->alive = 1;
    o->body.id = t->n;
    t->unready = 1;
    t->obj[t->n] = o;
    if (id) *id = t->n;
    t->n++;
    index_add(t, t->n - 1);
    return 0;
}

static int off_from_text(const char *text, vrPolyhedron **p, char *err, size_t n)
{
    char path[] = "/tmp/vroc-off-XXXXXX";
    int fd = mkstemp(path), r;
    FILE *f = fd >= 0 ? fdopen(fd, "w") : NULL;
    if (!f) return vrGeom_Fail(err, n, "cannot write a temporary OFF file");
    r = fputs(text, f) < 0;
    r |= fclose(f) != 0;
    r = r ? vrGeom_Fail(err, n, "cannot write a temporary OFF file") : vrPolyhedron_FromOFF(path, p, err, n);
    unlink(path);
    return r;
}

int vrTable_Put(vrTable *t, int id, const vrObjectDef *def, const char *off_text, char *err, size_t n)
{
    vrObject *o;
    if (id < 0 || vrObjectDef_Check(def, err, n) != 0) return -1;
    while (t->n <= id) {
        if (room_for_one_more(t, err, n) != 0) return -1;
        t->obj[t->n++] = NULL;
    }
    vrObject_Free(t->obj[id]);
    t->obj[id] = o = calloc(1, sizeof *o);
    if (!o) return vrGeom_Fail(err, n, "out of memory");
    snprintf(o->name, sizeof o->name, "#%d", id);
    o->def = *def;
    o->alive = 1;
    o->body.id = id;
    t->unready = 1;
    if (def->type == VR_POLYHEDRON && (!off_text || off_from_text(off_text, &o->off, err, n) != 0))
        return off_text ? -1 : vrGeom_Fail(err, n, "polyhedron without its OFF text");
    return 0;
}

int vrTable_Count(const vrTable *t)
{
    int i, n = 0;
    for (i = 0; i < t->n; i++) n += t->obj[i] != NULL;
    return n;
}

int vrTable_List(const vrTable *t, int *ids, int max)
{
    int i, n = 0;
    for (i = 0; i < t->n; i++)
        if (t->obj[i]) {
            if (n < max) ids[n] = i;
            n++;
        }
    return n;
}

void vrTable_Clear(vrTable *t)
{
    int i;
    for (i = 0; i < t->n; i++) vrObject_Free(t->obj[i]);
    t->n = 0;
    free(t->index);
    t->index = NULL;
    t->indexcap = t->nindex = 0;
}

void vrTable_Free(vrTable *t)
{
    vrTable_Clear(t);
    free(t->obj);
    t->obj = NULL;
    t->cap = 0;
}

int vrTable_LivePair(const vrTable *t, int i, int j)
{
    const vrObject *a = t->obj[i], *b = t->obj[j];
    return a && b && a->live && b->live && !(a->body.is_static && b->body.is_static);
}

unsigned char *vrTable_PendingMarks(const vrTable *t, const vrUpdate *pending)
{
    unsigned char *mark = calloc((size_t)t->n + 1, 1);
    int i;
    /* An owed overlap check (an edit since the last start, or a start
     * refused) looks at the flagged pairs of the bodies it is owed for:
     * owners made anew now, e.g. for a new pair set after an edit that only
     * changed a mass, must flag those, or an overlap the old owners had
     * flagged goes unseen. */
    for (i = 0; mark && i < t->n; i++)
        if (t->obj[i] && t->obj[i]->overlap_owed) mark[i] = 1;
    for (i = 0; mark && i < pending->n; i++)
        if (pending->body[i].id >= 0 && pending->body[i].id < t->n) mark[pending->body[i].id] = 1;
    return mark;
}

int vrObject_SetDef(vrObject *o, const vrObjectDef *def, vrObjectDef *old, char *err, size_t n)
{
    if (def->type != o->def.type) return vrGeom_Fail(err, n, "an object's type cannot change");
    if (vrObjectDef_Check(def, err, n) != 0) return -1;
    if (def->type == VR_POLYHEDRON && def->file[0]
        && (strcmp(def->file, o->def.file) != 0 || memcmp(def->scale, o->def.scale, sizeof def->scale) != 0)) {
        vrPolyhedron *p = NULL;
        char *text;   /* the scaled vertices: what the workers build from */
        if (vrPolyhedron_FromOFFScaled(def->file, def->scale, &p, &text, err, n) != 0) return -1;
        vrPolyhedron_Free(o->off);
        free(o->off_text);
        o->off = p;
        o->off_text = text;
    }
    *old = o->def;
    o->def = *def;
    return 0;
}

void vrObject_FreeShape(vrObject *o)
{
    vrShape_Release(o->shape);
    o->shape = NULL;
}

void vrObject_Free(vrObject *o)
{
    if (!o) return;
    vrObject_FreeShape(o);
    vrPolyhedron_Free(o->off);
    free(o->off_text);
    free(o->saved);
    free(o);
}
