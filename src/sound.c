/* sound.c — collision sound events (SPEC 8): which impacts sound, how
 * loud, and the refractory time per pair.
 *
 *   latest_of, put_latest, remake_latest   each pair's latest sound, hashed
 *   forget_quiet   the pairs whose refractory time is over
 *   recent         whether a pair sounded within it
 *   vrSounds_Note  an impact: an event, or none
 *   vrSounds_Remember   a pair's last sound, read back from a save
 *
 * The speed of an impact is its approach n.u at the impulse's point, as
 * the owner found it when it found the event: the same bits whatever the
 * heap mode.  Volume rises linearly with it up to VR_SOUND_FULL_SPEED.
 */
#include <stdlib.h>
#include <string.h>
#include "grow.h"
#include "sound.h"

/* The pairs that sounded: `last` in the order they did (a save writes
 * them so), `latest` each pair's latest time by its order.  A pair is
 * recent when its latest sound is within the refractory time; the ones
 * past it are dropped in batches, when they could make up half of
 * `last` (a look at every pair at every impact cost 3 % of the peers'
 * 1,000 room, where some 1,000 pairs sound within 0.1 s). */
static unsigned long slot_of(long long order, int cap)
{
    unsigned long long h = (unsigned long long)order * 0x9e3779b97f4a7c15ULL;
    return (unsigned long)(h >> 32) & (unsigned long)(cap - 1);
}

static vrSoundLast *latest_of(const vrSounds *s, long long order)
{
    unsigned long k;
    if (!s->latestcap) return NULL;
    for (k = slot_of(order, s->latestcap); s->latest[k].order != -1; k = (k + 1) & (unsigned long)(s->latestcap - 1))
        if (s->latest[k].order == order) return &s->latest[k];
    return NULL;
}

/* the pair's latest sound at t (a later time of the two, if it had one) */
static void put_latest(vrSounds *s, long long order, double t)
{
    unsigned long k = slot_of(order, s->latestcap);
    while (s->latest[k].order != -1 && s->latest[k].order != order) k = (k + 1) & (unsigned long)(s->latestcap - 1);
    if (s->latest[k].order == -1) {
        s->latest[k].order = order;
        s->latest[k].t = t;
        s->nlatest++;
    } else if (t > s->latest[k].t) {
        s->latest[k].t = t;
    }
}

/* the table made anew for the pairs of `last`, with room for twice as many */
static int remake_latest(vrSounds *s)
{
    int cap = 64, i;
    vrSoundLast *m;
    while (cap < 4 * (s->nlast + 1)) cap *= 2;
    if (!(m = malloc((size_t)cap * sizeof *m))) return -1;
    for (i = 0; i < cap; i++) m[i].order = -1;
    free(s->latest);
    s->latest = m;
    s->latestcap = cap;
    s->nlatest = 0;
    for (i = 0; i < s->nlast; i++) put_latest(s, s->last[i].order, s->last[i].t);
    return 0;
}

/* drops the sounds past the refractory time at t */
static void forget_quiet(vrSounds *s, double t)
{
    int i, k = 0;
    for (i = 0; i < s->nlast; i++)
        if (t - s->last[i].t < VR_SOUND_REFRACTORY) s->last[k++] = s->last[i];
    s->nlast = k;
}

static int recent(const vrSounds *s, long long order, double t)
{
    const vrSoundLast *l = latest_of(s, order);
    return l && t - l->t < VR_SOUND_REFRACTORY;
}

int vrSounds_Note(vrSounds *s, const vrEvent *ev, const vrSettings *set)
{
    double speed = -ev->approach;
    vrSoundEvent *e;
    if (ev->kind != VR_EV_IMPACT && ev->kind != VR_EV_CONTACT) return 0;
    if (!(speed > set->sound_min_speed)) return 0;
    if (recent(s, ev->order, ev->t)) return 0;
    if (vrGrow((void **)&s->ev, &s->cap, s->n + 1, sizeof *s->ev) != 0 || vrSounds_Remember(s, ev->order, ev->t) != 0)
        return -1;
    e = &s->ev[s->n++];
    e->t = ev->t;
    e->speed = speed;
    e->volume = set->collision_vol * (speed < VR_SOUND_FULL_SPEED ? speed / VR_SOUND_FULL_SPEED : 1);
    e->position[0] = ev->c.x, e->position[1] = ev->c.y, e->position[2] = ev->c.z;
    e->a = ev->a;
    e->b = ev->b;
    return 0;
}

int vrSounds_Remember(vrSounds *s, long long order, double t)
{
    if (s->nlast >= 64 && s->nlast >= s->lastcap) {   /* full: the quiet ones go, and room for as many */
        forget_quiet(s, t);
        if (remake_latest(s) != 0) return -1;
    }
    if (vrGrow((void **)&s->last, &s->lastcap, 2 * s->nlast + 1, sizeof *s->last) != 0) return -1;
    s->last[s->nlast].order = order;
    s->last[s->nlast++].t = t;
    if (2 * (s->nlatest + 1) > s->latestcap) return remake_latest(s);
    put_latest(s, order, t);
    return 0;
}

void vrSounds_Frame(vrSounds *s) { s->n = 0; }

void vrSounds_Clear(vrSounds *s)
{
    int i;
    s->n = s->nlast = s->nlatest = 0;
    for (i = 0; i < s->latestcap; i++) s->latest[i].order = -1;
}

void vrSounds_Free(vrSounds *s)
{
    free(s->ev);
    free(s->last);
    free(s->latest);
    memset(s, 0, sizeof *s);
}
