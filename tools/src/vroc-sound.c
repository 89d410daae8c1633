/* vroc-sound — renders a collision sound log (SPEC 8) to a 16-bit WAV.
 *
 *   vroc-sound LOG OUT.wav
 *
 * LOG is what `sound_log = FILE` writes: lines t,sound,volume,x,y,z,speed
 * (`#` lines and blank lines skipped).  Each event is one copy of its
 * sound, scaled by its volume, starting at its time (the nearest sample);
 * the copies are added and clipped.  A sound is a built-in (`bounce`, the
 * default) or a sound file libsndfile reads (WAV, FLAC, OGG ...), its path
 * relative to the log's folder; a file's channels are averaged and its
 * rate converted by linear interpolation.  Mono, 44100 Hz.  The mix is
 * made a second at a time, so a long log needs no more memory than its
 * events.  Errors name the log and its line; the exit status is 1.
 *
 *   parse_line   one event
 *   builtin      the synthesised sounds
 *   load_file    a sound file, at the output rate
 *   mix          the output, block by block
 */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sndfile.h>

#define RATE 44100
#define MAX_T 3600.0          /* s: an hour of sound at most (317 MB of WAV) */
#define MAX_SOUND_S 10.0      /* s of a sound file used */
#define MAX_SOUNDS 64
#define PI 3.14159265358979323846

typedef struct Sound { char name[256]; float *s; long n; } Sound;
typedef struct Event { double t; double volume; long start; int sound; } Event;

static const char *log_path;
static char log_dir[4096];
static Sound sounds[MAX_SOUNDS];
static int nsounds;

static int fail(long line, const char *fmt, ...)
{
    va_list ap;
    fprintf(stderr, "vroc-sound: ");
    if (line > 0) fprintf(stderr, "%s:%ld: ", log_path, line);
    va_start(ap, fmt);
    vfprintf(stderr, fmt, ap);
    va_end(ap);
    fputc('\n', stderr);
    return -1;
}

/* the built-in `bounce`: a ball's knock, a low thump and a brighter
 * click, each dying away, 0.25 s, peak about 1 */
static int builtin(Sound *snd)
{
    long i, n = (long)(0.25 * RATE);
    if (strcmp(snd->name, "bounce") != 0) return 1;
    snd->s = malloc((size_t)n * sizeof *snd->s);
    if (!snd->s) return -1;
    for (i = 0; i < n; i++) {
        double t = (double)i / RATE, attack = t < 0.001 ? t / 0.001 : 1;
        snd->s[i] = (float)(attack * (0.75 * sin(2 * PI * 170 * t) * exp(-t / 0.05)
                                      + 0.25 * sin(2 * PI * 900 * t) * exp(-t / 0.01)));
    }
    snd->n = n;
    return 0;
}

static int resample(Sound *snd, const float *in, long frames, int channels, int rate, long line)
{
    long n = (long)floor((double)frames * RATE / rate), i;
    if (n < 1) return fail(line, "sound file '%s' is empty", snd->name);
    snd->s = malloc((size_t)n * sizeof *snd->s);
    if (!snd->s) return fail(line, "out of memory");
    for (i = 0; i < n; i++) {
        double x = (double)i * rate / RATE, a = 0, b = 0;
        long k = (long)x, c;
        for (c = 0; c < channels; c++) {
            a += in[k * channels + c];
            b += in[(k + 1 < frames ? k + 1 : k) * channels + c];
        }
        snd->s[i] = (float)(((1 - (x - k)) * a + (x - k) * b) / channels);
    }
    snd->n = n;
    return 0;
}

static int load_file(Sound *snd, long line)
{
    char path[8192];
    SF_INFO info;
    SNDFILE *f;
    float *in;
    long frames;
    int r;
    if (snd->name[0] == '/' || !log_dir[0]) snprintf(path, sizeof path, "%s", snd->name);
    else snprintf(path, sizeof path, "%s/%s", log_dir, snd->name);
    memset(&info, 0, sizeof info);
    f = sf_open(path, SFM_READ, &info);
    if (!f) return fail(line, "sound '%s' is no built-in (bounce) and %s cannot be read: %s", snd->name, path, sf_strerror(NULL));
    frames = info.frames < (sf_count_t)(MAX_SOUND_S * info.samplerate) ? (long)info.frames : (long)(MAX_SOUND_S * info.samplerate);
    in = info.channels > 0 && frames > 0 ? malloc((size_t)frames * (size_t)info.channels * sizeof *in) : NULL;
    if (!in) {
        sf_close(f);
        return fail(line, "sound file %s is empty or too large", path);
    }
    frames = (long)sf_readf_float(f, in, frames);
    sf_close(f);
    r = resample(snd, in, frames, info.channels, info.samplerate, line);
    free(in);
    return r;
}

/* the sound's index, loaded on first use */
static int sound_of(const char *name, long line)
{
    int i, r;
    for (i = 0; i < nsounds; i++)
        if (strcmp(sounds[i].name, name) == 0) return i;
    if (nsounds == MAX_SOUNDS) return fail(line, "more than %d different sounds", MAX_SOUNDS);
    snprintf(sounds[nsounds].name, sizeof sounds[nsounds].name, "%s", name);
    r = builtin(&sounds[nsounds]);
    if (r == 1) r = load_file(&sounds[nsounds], line);
    else if (r < 0) r = fail(line, "out of memory");
    return r == 0 ? nsounds++ : -1;
}

static int number(char *field, long line, const char *what, double lo, double hi, double *v)
{
    char *end;
    if (!field) return fail(line, "missing %s (a line is t,sound,volume,x,y,z,speed)", what);
    *v = strtod(field, &end);
    if (end == field || *end || strpbrk(field, "xXnNiI") || !(*v >= lo && *v <= hi))
        return fail(line, "%s must be a number %g..%g (got '%.40s')", what, lo, hi, field);
    return 0;
}

static int parse_line(char *text, long line, Event *ev)
{
    char *f[8], *p = text;
    double unused;
    int k = 0, i;
    while (k < 8 && p) {
        f[k++] = p;
        p = strchr(p, ',');
        if (p) *p++ = '\0';
    }
    if (k != 7) return fail(line, "expected 7 fields t,sound,volume,x,y,z,speed (got %d)", k);
    if (number(f[0], line, "t", 0, MAX_T, &ev->t) != 0 || number(f[2], line, "volume", 0, 1, &ev->volume) != 0) return -1;
    for (i = 3; i < 7; i++)
        if (number(f[i], line, i == 6 ? "speed" : "position", -1e300, 1e300, &unused) != 0) return -1;
    if (!f[1][0]) return fail(line, "empty sound name");
    ev->sound = sound_of(f[1], line);
    ev->start = lround(ev->t * RATE);
    return ev->sound < 0 ? -1 : 0;
}

static int by_start(const void *x, const void *y)
{
    const Event *a = x, *b = y;
    return a->start < b->start ? -1 : a->start > b->start;
}

static int read_log(FILE *in, Event **evs, long *nev)
{
    char *buf = NULL;
    size_t cap = 0;
    ssize_t len;
    long line = 0, evcap = 0;
    int r = 0;
    while (r == 0 && (len = getline(&buf, &cap, in)) >= 0) {
        line++;
        while (len > 0 && (buf[len - 1] == '\n' || buf[len - 1] == '\r')) buf[--len] = '\0';
        if (len == 0 || buf[0] == '#') continue;
        if (*nev == evcap) {
            Event *m = realloc(*evs, (size_t)(evcap = evcap ? 2 * evcap : 256) * sizeof *m);
            if (!m) { r = fail(line, "out of memory"); break; }
            *evs = m;
        }
        r = parse_line(buf, line, &(*evs)[*nev]);
        if (r == 0) (*nev)++;
    }
    free(buf);
    return r;
}

/* the output a block at a time: the events that sound in it, added */
static int mix(SNDFILE *out, const Event *ev, long nev)
{
    long block = RATE, total = RATE / 10, longest = 0, lo = 0, at, i;
    float *buf = malloc((size_t)block * sizeof *buf);
    if (!buf) return fail(0, "out of memory");
    for (i = 0; i < nsounds; i++)
        if (sounds[i].n > longest) longest = sounds[i].n;
    for (i = 0; i < nev; i++)
        if (ev[i].start + sounds[ev[i].sound].n > total) total = ev[i].start + sounds[ev[i].sound].n;
    for (at = 0; at < total; at += block) {
        long n = total - at < block ? total - at : block, k;
        memset(buf, 0, (size_t)n * sizeof *buf);
        while (lo < nev && ev[lo].start + longest <= at) lo++;   /* sorted by start: over */
        for (i = lo; i < nev && ev[i].start < at + n; i++) {
            const Sound *s = &sounds[ev[i].sound];
            for (k = ev[i].start > at ? ev[i].start - at : 0; k < n && at + k - ev[i].start < s->n; k++)
                buf[k] += (float)ev[i].volume * s->s[at + k - ev[i].start];
        }
        for (k = 0; k < n; k++) buf[k] = buf[k] > 1 ? 1 : buf[k] < -1 ? -1 : buf[k];
        if (sf_writef_float(out, buf, n) != n) {
            free(buf);
            return fail(0, "cannot write: %s", sf_strerror(out));
        }
    }
    free(buf);
    return 0;
}

static int render(const char *wav, Event *ev, long nev)
{
    SF_INFO info;
    SNDFILE *out;
    int r;
    memset(&info, 0, sizeof info);
    info.samplerate = RATE;
    info.channels = 1;
    info.format = SF_FORMAT_WAV | SF_FORMAT_PCM_16;
    qsort(ev, (size_t)nev, sizeof *ev, by_start);
    out = sf_open(wav, SFM_WRITE, &info);
    if (!out) return fail(0, "cannot write %s: %s", wav, sf_strerror(NULL));
    r = mix(out, ev, nev);
    if (sf_close(out) != 0 && r == 0) r = fail(0, "cannot write %s", wav);
    return r;
}

int main(int argc, char **argv)
{
    FILE *in;
    Event *ev = NULL;
    long nev = 0;
    int r, i;
    char *slash;
    if (argc != 3) {
        fprintf(stderr, "usage: vroc-sound LOG OUT.wav\n");
        return 2;
    }
    log_path = argv[1];
    snprintf(log_dir, sizeof log_dir, "%s", argv[1]);
    slash = strrchr(log_dir, '/');
    if (slash) *slash = '\0';
    else log_dir[0] = '\0';
    in = fopen(log_path, "r");
    if (!in) return fail(0, "cannot open %s: %s", log_path, strerror(errno)), 1;
    r = read_log(in, &ev, &nev);
    fclose(in);
    if (r == 0) r = render(argv[2], ev, nev);
    free(ev);
    for (i = 0; i < nsounds; i++) free(sounds[i].s);
    return r == 0 ? 0 : 1;
}
