/* track_file.c — a track file (SPEC 8): one sample a line,
 * `t device x y z qw qx qy qz [buttons]`, `#` to the line's end a comment,
 * times never decreasing.  Every bad line is an error naming the file and
 * the line; nothing is handed on before the whole file has been read.
 *
 *   number       one decimal number (the shell's forms: no hex, inf, nan)
 *   parse_line   a line into a device and a sample
 *   read_lines   every line of the stream, each handed to the callback
 */
#define _POSIX_C_SOURCE 200809L /* NOLINT(bugprone-reserved-identifier): the feature test macro POSIX names */
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "vroc.h"

/* a unit quaternion is one to this much (written with 6 decimals, a
 * tracker's quaternion is unit to about 1e-6); it is normalised after */
#define VR_UNIT_TOLERANCE 1e-5

typedef struct Line {
    char *p;
    const char *path;
    long no;
    char *err;
    size_t n;
} Line;

static int fail(Line *l, const char *fmt, ...)
{
    char msg[400];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    snprintf(l->err, l->n, "%s:%ld: %s", l->path, l->no, msg);
    return -1;
}

/* the next blank-separated word, NUL-terminated in place; NULL at the end */
static char *word(Line *l)
{
    char *w;
    while (*l->p == ' ' || *l->p == '\t') l->p++;
    if (!*l->p) return NULL;
    w = l->p;
    while (*l->p && *l->p != ' ' && *l->p != '\t') l->p++;
    if (*l->p) *l->p++ = '\0';
    return w;
}

static int number(Line *l, const char *what, double *v)
{
    char *w = word(l), *end;
    if (!w) return fail(l, "missing %s (a line is: t device x y z qw qx qy qz [buttons])", what);
    errno = 0;
    *v = strtod(w, &end);
    if (*end || strpbrk(w, "xXnNiI") || !isfinite(*v))
        return fail(l, "%s must be a finite decimal number (got '%.40s')", what, w);
    return 0;
}

static int device_of(Line *l, vrDevice *dev)
{
    char *w = word(l);
    if (!w) return fail(l, "missing device (head or hand)");
    if (strcmp(w, "head") == 0) *dev = VR_DEVICE_HEAD;
    else if (strcmp(w, "hand") == 0) *dev = VR_DEVICE_HAND;
    else return fail(l, "unknown device '%.40s' (head or hand)", w);
    return 0;
}

static int buttons_of(Line *l, vrDevice dev, vrTrackerSample *s)
{
    double b;
    char *rest;
    s->buttons = 0;
    while (*l->p == ' ' || *l->p == '\t') l->p++;
    if (!*l->p) return 0;
    if (dev == VR_DEVICE_HEAD) return fail(l, "a head sample has no buttons (got '%.40s')", l->p);
    if (number(l, "buttons", &b) != 0) return -1;
    if (b != floor(b) || b < 0 || b > 3) return fail(l, "buttons must be an integer 0..3 (1 trigger, 2 reselect; got %g)", b);
    s->buttons = (unsigned)b;
    rest = word(l);
    if (rest) return fail(l, "unexpected '%.40s' after the sample", rest);
    return 0;
}

static int quaternion(Line *l, vrTrackerSample *s)
{
    static const char *const names[4] = {"qw", "qx", "qy", "qz"};
    double len = 0;
    int i;
    for (i = 0; i < 4; i++) {
        if (number(l, names[i], &s->orientation[i]) != 0) return -1;
        len += s->orientation[i] * s->orientation[i];
    }
    len = sqrt(len);
    if (!(fabs(len - 1) <= VR_UNIT_TOLERANCE)) return fail(l, "the quaternion must be a unit one (its length is %.9g)", len);
    for (i = 0; i < 4; i++) s->orientation[i] /= len;
    return 0;
}

static int parse_line(Line *l, double last_t, vrDevice *dev, vrTrackerSample *s)
{
    static const char *const names[3] = {"x", "y", "z"};
    int i;
    if (number(l, "t", &s->t) != 0) return -1;
    if (s->t < 0) return fail(l, "t must be >= 0 (got %g)", s->t);
    if (s->t < last_t) return fail(l, "times never decrease (t %.17g after %.17g)", s->t, last_t);
    if (device_of(l, dev) != 0) return -1;
    for (i = 0; i < 3; i++)
        if (number(l, names[i], &s->position[i]) != 0) return -1;
    if (quaternion(l, s) != 0) return -1;
    return buttons_of(l, *dev, s);
}

/* the line without its end (LF, CRLF) and comment; NUL and control bytes refused */
static int clean(Line *l, char *buf, ssize_t len)
{
    ssize_t i;
    l->p = buf;
    for (i = 0; i < len; i++) {
        unsigned char c = (unsigned char)buf[i];
        if (c == '#' || c == '\n' || (c == '\r' && i == len - 2 && buf[i + 1] == '\n')) break;
        if (c == '\t') continue;
        if (c < 32 || c == 127) return fail(l, "control byte 0x%02x in the line", c);
    }
    buf[i] = '\0';
    l->p = buf;
    return 0;
}

static int read_lines(FILE *f, const char *path, vrTrackSampleFn fn, void *user, char *err, size_t n)
{
    char *buf = NULL;
    size_t cap = 0;
    ssize_t len;
    double last_t = 0;
    Line l;
    int r = 0;
    l.path = path, l.no = 0, l.err = err, l.n = n;
    while (r == 0 && (len = getline(&buf, &cap, f)) >= 0) {
        vrTrackerSample s;
        vrDevice dev = VR_DEVICE_HEAD;
        char msg[400];
        l.no++;
        if (clean(&l, buf, len) != 0) {
            r = -1;
            break;
        }
        l.p += strspn(l.p, " \t");
        if (!*l.p) continue;
        memset(&s, 0, sizeof s);
        if ((r = parse_line(&l, last_t, &dev, &s)) != 0) break;
        last_t = s.t;
        if ((r = fn(user, dev, &s, msg, sizeof msg)) != 0) fail(&l, "%s", msg);
    }
    if (r == 0 && ferror(f)) r = fail(&l, "read error");
    free(buf);
    return r;
}

int vrTrackFile_Read(const char *path, vrTrackSampleFn fn, void *user, char *err, size_t n)
{
    FILE *f = fopen(path, "r");
    int r;
    if (!f) {
        snprintf(err, n, "cannot open track file %s: %s", path, strerror(errno));
        return -1;
    }
    r = read_lines(f, path, fn, user, err, n);
    fclose(f);
    return r;
}
