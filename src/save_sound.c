/* save_sound.c — the collision sounds' section of a saved file
 * (save_sections.h):
 *   sound_pair   a pair that sounded within the refractory time (sound.h):
 *                an impact of it just after the save is quiet in the
 *                reader as in the saving run, so the sound log goes on
 *                with the same events.
 *
 * A pair is written by its objects' names, like a warm start; a pair
 * whose refractory time is over at the clock's time is not written (no
 * later impact could be kept quiet by it: times only grow), nor one whose
 * object was deleted (it cannot sound again).
 */
#include "broadphase.h"
#include "save_sections.h"

static int pair_ids(long long order, int *a, int *b)
{
    *a = (int)(order >> 32);
    *b = (int)(order & 0xffffffffLL);
    return *a >= 0 && *b > *a;
}

void vrSave_WriteSoundPairs(vrWorld *w, int id, FILE *out)
{
    const vrSounds *s = &w->sounds;
    int i, a, b;
    (void)id;
    for (i = 0; i < s->nlast; i++) {
        if (!(w->t - s->last[i].t < VR_SOUND_REFRACTORY) || !pair_ids(s->last[i].order, &a, &b)) continue;
        if (!vrWorld_Object(w, a) || !vrWorld_Object(w, b)) continue;
        fprintf(out, "state sound_pair a=%s b=%s", w->table.obj[a]->name, w->table.obj[b]->name);
        vrSave_Number(out, "t", s->last[i].t);
        fputc('\n', out);
    }
}

int vrSave_ReadSoundPair(vrWorld *w, int id, vrSaveLine *l, char *err, size_t n)
{
    int a, b;
    double t;
    (void)id;
    if (vrSave_GetObject(w, l, "a", &a, err, n) || vrSave_GetObject(w, l, "b", &b, err, n)
        || vrSaveLine_Numbers(l, "t", &t, 1, 0, err, n))
        return -1;
    if (a >= b) {
        snprintf(err, n, "state sound_pair: a must be the object made first");
        return -1;
    }
    if (t > w->t) {
        snprintf(err, n, "state sound_pair: t must not be after the clock's time");
        return -1;
    }
    if (vrSounds_Remember(&w->sounds, vrPair_Order(a, b), t) != 0) {
        snprintf(err, n, "out of memory");
        return -1;
    }
    return 0;
}
