/* save_track.c — the trackers' section of a saved file (save_sections.h):
 *   sample   one sample of the head or the hand that the run still needs:
 *            its absolute world time, position, orientation (w, x, y, z)
 *            and buttons, so that a run saved while a track file plays
 *            (or a live tracker sends) goes on with the same poses, the
 *            same view and the same hand.
 *
 * Only the samples a time from the save on needs are written (the last
 * at or before the clock's time and all after it, track.h's Forget), and
 * the saving run forgets the others too, so that it holds what its file
 * holds.  A live tracker is not reconnected by the reader: its samples
 * received are written like a track file's (the shell's comment says so).
 */
#include <math.h>
#include <string.h>
#include "save_sections.h"

static const char *const device_words[2] = {"head", "hand"};

static void write_sample(FILE *out, int dev, const vrTrackerSample *s)
{
    fprintf(out, "state sample device=%s", device_words[dev]);
    vrSave_Number(out, "t", s->t);
    vrSave_Vector(out, "x", s->position, 3);
    vrSave_Vector(out, "q", s->orientation, 4);
    vrSave_Integer(out, "buttons", s->buttons);
    fputc('\n', out);
}

void vrSave_WriteSamples(vrWorld *w, int id, FILE *out)
{
    int dev, i;
    (void)id;
    for (dev = 0; dev < 2; dev++) {
        vrTrack *tr = &w->track[dev];
        vrTrack_Forget(tr, w->t);
        for (i = 0; i < tr->n; i++) write_sample(out, dev, &tr->s[i]);
    }
}

static int get_device(vrSaveLine *l, int *dev, char *err, size_t n)
{
    char word[8];
    if (vrSaveLine_Word(l, "device", word, sizeof word, err, n) != 0) return -1;
    for (*dev = 0; *dev < 2; (*dev)++)
        if (strcmp(word, device_words[*dev]) == 0) return 0;
    snprintf(err, n, "state sample: device must be head or hand (got '%s')", word);
    return -1;
}

/* a tracker's orientation is a unit quaternion: kept as read, bit for bit */
static int get_orientation(vrSaveLine *l, double q[4], char *err, size_t n)
{
    quat r;
    if (vrSave_GetQuat(l, "q", &r, err, n) != 0) return -1;
    q[0] = r.w, q[1] = r.x, q[2] = r.y, q[3] = r.z;
    return 0;
}

static int get_sample(vrSaveLine *l, int dev, vrTrackerSample *s, char *err, size_t n)
{
    long long buttons;
    if (vrSaveLine_Numbers(l, "t", &s->t, 1, 0, err, n) || vrSaveLine_Numbers(l, "x", s->position, 3, 0, err, n)
        || get_orientation(l, s->orientation, err, n)
        || vrSaveLine_Integer(l, "buttons", 0, 3, &buttons, err, n))
        return -1;
    if (dev == VR_DEVICE_HEAD && buttons != 0) {
        snprintf(err, n, "state sample: a head has no buttons (buttons=0)");
        return -1;
    }
    if (s->t < 0) {
        snprintf(err, n, "state sample: t must be >= 0");
        return -1;
    }
    s->buttons = (unsigned)buttons;
    return 0;
}

int vrSave_ReadSample(vrWorld *w, int id, vrSaveLine *l, char *err, size_t n)
{
    vrTrackerSample s;
    vrTrack *tr;
    int dev;
    (void)id;
    memset(&s, 0, sizeof s);
    if (get_device(l, &dev, err, n) != 0 || get_sample(l, dev, &s, err, n) != 0) return -1;
    tr = &w->track[dev];
    if (tr->n > 0 && s.t < tr->s[tr->n - 1].t) {
        char a[32], b[32];
        vrFormatExact(a, s.t);
        vrFormatExact(b, tr->s[tr->n - 1].t);
        snprintf(err, n, "state sample: times never decrease (t %s after the %s's %s)", a, device_words[dev], b);
        return -1;
    }
    if (vrTrack_Push(tr, &s) != 0) {
        snprintf(err, n, "out of memory");
        return -1;
    }
    return 0;
}
