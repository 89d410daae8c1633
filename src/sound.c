/* sound.c — collision sound events (SPEC 8): which impacts sound, how
 * loud, and the refractory time per pair.
 *
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
#include "sound.h"

static int grow(void **p, int *cap, int need, size_t size)
{
    int c = *cap ? *cap : 16;
    void *m;
    if (need <= *cap) return 0;
    while (c < need) c *= 2;
    m = realloc(*p, (size_t)c * size);
    if (!m) return -1;
    *p = m;
    *cap = c;
    return 0;
}

static void forget_quiet(vrSounds *s, double t)
{
    int i, k = 0;
    for (i = 0; i < s->nlast; i++)
        if (t - s->last[i].t < VR_SOUND_REFRACTORY) s->last[k++] = s->last[i];
    s->nlast = k;
}

static int recent(const vrSounds *s, long long order)
{
    int i;
    for (i = 0; i < s->nlast; i++)
        if (s->last[i].order == order) return 1;
    return 0;
}

int vrSounds_Note(vrSounds *s, const vrEvent *ev, const vrSettings *set)
{
    double speed = -ev->approach;
    vrSoundEvent *e;
    if (ev->kind != VR_EV_IMPACT && ev->kind != VR_EV_CONTACT) return 0;
    if (!(speed > set->sound_min_speed)) return 0;
    forget_quiet(s, ev->t);
    if (recent(s, ev->order)) return 0;
    if (grow((void **)&s->ev, &s->cap, s->n + 1, sizeof *s->ev) != 0 || vrSounds_Remember(s, ev->order, ev->t) != 0)
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
    if (grow((void **)&s->last, &s->lastcap, s->nlast + 1, sizeof *s->last) != 0) return -1;
    s->last[s->nlast].order = order;
    s->last[s->nlast++].t = t;
    return 0;
}

void vrSounds_Frame(vrSounds *s) { s->n = 0; }

void vrSounds_Clear(vrSounds *s) { s->n = s->nlast = 0; }

void vrSounds_Free(vrSounds *s)
{
    free(s->ev);
    free(s->last);
    memset(s, 0, sizeof *s);
}
