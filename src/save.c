/* save.c — the sections of a saved file and their driver (save.h).
 *   sections            every piece of state, in the order it is written
 *   vrWorld_WriteSave   the file: definitions (the shell's) and sections
 *   vrWorld_ReadState   one `state` line
 *   vrSave_Resume       what the start puts back
 */
#include <stdlib.h>
#include <string.h>
#include "owners.h"
#include "saved.h"
#include "save_sections.h"

#define STATE_KEYS "x v q L rest hit contact island"
#define POINT_KEYS "p0 impulse0 p1 impulse1 p2 impulse2 p3 impulse3 p4 impulse4 p5 impulse5 p6 impulse6 p7 impulse7"
static const vrSaveSection sections[] = {
    {"body", "t0 " STATE_KEYS " quiet owed frame_x frame_q", 1, vrSave_WriteBody, vrSave_ReadBody},
    {"clock", "t frames t_base frames_base instant instant_t settings_due", 0, vrSave_WriteClock, vrSave_ReadClock},
    {"counters", "collisions island_steps island_contacts checks heap_pops klu_solves klu_refactors klu_factors subframes",
     0, vrSave_WriteCounters, vrSave_ReadCounters},
    {"random", "next stream", 0, vrSave_WriteRandom, vrSave_ReadRandom},
    {"warm", "a b h n points " POINT_KEYS " friction twist", 0, vrSave_WriteWarm, vrSave_ReadWarm},
    {"pending", "obj t raw " STATE_KEYS, 0, vrSave_WritePending, vrSave_ReadPending},
    {"gap", "", 0, NULL, vrSave_ReadGap},   /* written by the driver, for a deleted object's id */
};
#define NSECTIONS ((int)(sizeof sections / sizeof sections[0]))

static void write_sections(vrWorld *w, int id, int per_object, FILE *out)
{
    int k;
    for (k = 0; k < NSECTIONS; k++)
        if (sections[k].write && sections[k].per_object == per_object) sections[k].write(w, id, out);
}

int vrWorld_WriteSave(vrWorld *w, FILE *out, vrDefWriter def, void *ctx)
{
    int i;
    vrOwners_Retire(w);
    fputs("\n# objects, by id: each definition, then where its run has taken it\n", out);
    for (i = 0; i < w->table.n; i++) {
        if (!w->table.obj[i]) {
            fputs("state gap\n", out);
            continue;
        }
        def(ctx, out, i);
        write_sections(w, i, 1, out);
    }
    fputs("\n# the run: clock, counters, random stream, warm starts, states not yet heard by the owners\n", out);
    write_sections(w, VR_NO_OBJECT, 0, out);
    return ferror(out) ? -1 : 0;
}

static const vrSaveSection *find_section(const char *word, size_t len)
{
    int k;
    for (k = 0; k < NSECTIONS; k++)
        if (strlen(sections[k].word) == len && memcmp(sections[k].word, word, len) == 0) return &sections[k];
    return NULL;
}

static void list_sections(char *buf, size_t n)
{
    int k;
    buf[0] = '\0';
    for (k = 0; k < NSECTIONS; k++) {
        size_t len = strlen(buf);
        snprintf(buf + len, n - len, "%s%s", k ? ", " : "", sections[k].word);
    }
}

int vrWorld_ReadState(vrWorld *w, vrObjectId selected, const char *text, size_t len, char *err, size_t n)
{
    const vrSaveSection *s;
    vrSaveLine l;
    size_t k = 0;
    char words[160];
    while (k < len && text[k] != ' ' && text[k] != '\t') k++;
    if (!(s = find_section(text, k))) {
        list_sections(words, sizeof words);
        snprintf(err, n, "unknown state '%.*s' (one of %s)", (int)(k > 40 ? 40 : k), text, words);
        return -1;
    }
    if (w->started) {
        snprintf(err, n, "state %s: a saved run is read into a world not yet started (restart first)", s->word);
        return -1;
    }
    if (vrSaveLine_Parse(&l, s->word, text + k, len - k, err, n) != 0 || vrSaveLine_Known(&l, s->keys, err, n) != 0)
        return -1;
    if (s->read(w, selected, &l, err, n) != 0) return -1;
    return vrSaveLine_Done(&l, err, n);
}

vrResume *vrSave_Resumed(vrWorld *w)
{
    if (!w->resume && (w->resume = calloc(1, sizeof *w->resume))) vrUpdate_Init(&w->resume->pending);
    return w->resume;
}

void vrSave_Free(vrWorld *w)
{
    if (!w->resume) return;
    vrUpdate_Free(&w->resume->pending);
    free(w->resume);
    w->resume = NULL;
}

/* the bodies read let go of their saved states; 1 when there were any */
static int release_saved(vrWorld *w)
{
    int i, any = 0;
    for (i = 0; i < w->table.n; i++) {
        vrObject *o = w->table.obj[i];
        if (!o || !o->saved || !o->live) continue;
        o->overlap_owed = o->saved->overlap_owed;
        free(o->saved);
        o->saved = NULL;
        any = 1;
    }
    return any;
}

/* the owners' unheard states: the saved ones, and those of objects that
 * went live placed by their definitions (added to the file by hand) */
static int merge_pending(vrWorld *w, const vrResume *r)
{
    int i, k = 0;
    for (i = 0; i < w->pending.n; i++) {
        const vrObject *o = vrWorld_Object(w, w->pending.body[i].id);
        if (o && !o->saved) w->pending.body[k++] = w->pending.body[i];
    }
    w->pending.n = k;
    for (i = 0; i < r->pending.n; i++) {
        vrBodyState *st;
        vrObject *o = vrWorld_Object(w, r->pending.body[i].id);
        if (!o || !o->live) continue;
        if (!(st = vrUpdate_Body(&w->pending, &o->body, w->t))) return -1;
        *st = r->pending.body[i];
    }
    return 0;
}

int vrSave_Resume(vrWorld *w)
{
    vrResume *r = w->resume;
    int i;
    if (r && merge_pending(w, r) != 0) return -1;
    if (release_saved(w)) {
        w->may_rest = 0;                 /* rest.c counts the resting at frame ends */
        for (i = 0; i < w->table.n; i++)
            if (w->table.obj[i] && w->table.obj[i]->live) w->may_rest += w->table.obj[i]->body.resting;
    }
    if (!r) return 0;
    if (r->warm) {
        vrWarm_Sort(&w->warm);
        w->warm.structure = w->structure;
    }
    vrSave_Free(w);
    return 0;
}
