/* save.c — the sections of a saved file and their driver (save.h).
 *   sections            every piece of state, in the order it is written
 *   vrWorld_WriteSave   the file: definitions (the shell's) and sections
 *   vrWorld_ReadState   one `state` line: its section found in the table
 */
#include <string.h>
#include "owners.h"
#include "save_sections.h"

#define STATE_KEYS "x v q L rest hit contact island"
#define POINT_KEYS "p0 impulse0 p1 impulse1 p2 impulse2 p3 impulse3 p4 impulse4 p5 impulse5 p6 impulse6 p7 impulse7"
static const vrSaveSection sections[] = {
    {"body", "t0 " STATE_KEYS " quiet slow slow_start owed frame_x frame_q", 1, vrSave_WriteBody, vrSave_ReadBody},
    {"clock", "t frames t_base frames_base instant instant_t settings_due", 0, vrSave_WriteClock, vrSave_ReadClock},
    {"counters", "collisions island_steps island_contacts checks heap_pops klu_solves klu_refactors klu_factors subframes clamps",
     0, vrSave_WriteCounters, vrSave_ReadCounters},
    {"random", "next stream", 0, vrSave_WriteRandom, vrSave_ReadRandom},
    {"warm", "a b h n points " POINT_KEYS " friction twist", 0, vrSave_WriteWarm, vrSave_ReadWarm},
    {"pending", "obj t raw " STATE_KEYS, 0, vrSave_WritePending, vrSave_ReadPending},
    {"sample", "device t x q buttons", 0, vrSave_WriteSamples, vrSave_ReadSample},
    {"sound_pair", "a b t", 0, vrSave_WriteSoundPairs, vrSave_ReadSoundPair},
    {"panel", "p q hold knob grip_p grip_q u moved", 0, vrSave_WritePanel, vrSave_ReadPanel},
    /* New state goes here, one line: its word (read as `state WORD ...`;
     * the dispatcher below finds it by this table, nothing else to add),
     * the keys its lines may hold, per object or not, and its writer and
     * reader (save_sections.h).  The grab's state (src/grab*.c) is one:
     * written after the samples it holds on to, before `live`. */
    {"gap", "", 0, NULL, vrSave_ReadGap},   /* written by the driver, for a deleted object's id */
    {"grab", VR_GRAB_SAVE_KEYS, 0, vrGrab_Save, vrGrab_Read},   /* the hand's (grab.h) */
    {"live", "", 0, vrSave_WriteLive, vrSave_ReadLive},   /* last: the saved run goes live */
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
    fputs("\n# the run: clock, counters, random stream, warm starts, states not yet heard by the owners,\n"
          "# the head's and hand's samples still needed, the pairs whose sound is still refractory\n", out);
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
    /* a new `state WORD` needs no code here: a line in sections[] */
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
