/* off.c — a convex polyhedron from an OFF file (SPEC 1.1, `polyhedron`).
 *
 * The format (Geomview's OFF): a header line `OFF` or `COFF`, the counts
 * `nv nf [ne]` (on the header line or the next), nv lines `x y z` (COFF:
 * `x y z r g b [a]`, the colour ignored), nf lines `k i1 .. ik` (a colour
 * may follow the indices: ignored).  `#` starts a comment; blank lines are
 * skipped.
 *
 * The polyhedron is the convex hull of the vertices (quickhull, hull.c),
 * whatever the faces say: a non-convex model collides as its hull, as the
 * man page says.  The faces are still read and checked, so that a broken
 * file is named, not half taken.  The vertices are scaled first (the
 * `scale` attribute); the scaled vertices can be written back as OFF text
 * (off_text) that gives the same polyhedron bit for bit with scale 1: that
 * is what the workers receive.
 *
 *   read_header, read_vertices, read_faces, read_off   the file
 *   scale_vertices   the scale, and the sane-coordinates limit
 *   off_text         the scaled vertices as OFF text
 */
#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <stdio.h>
#include <ctype.h>
#include "grow.h"
#include "hull.h"
#include "off.h"
#include "vroc.h"

/* facets within this (relative) merge: OFF files are often written with
 * six or seven significant digits */
#define OFF_TOL 1e-6
#define OFF_MAX_COUNT 100000000 /* keeps every size an int */

typedef struct Reader {
    FILE *f;
    const char *path;
    int line;
    char *buf;
    size_t cap;
    char **tok;
    int ntok, captok;
} Reader;

/* The arrays grow with the lines read, never trusting the counts: a file
 * claiming 10^8 vertices in three lines costs three lines of memory. */
typedef struct Off {
    int nv, nf;
    int coloured;        /* COFF: a colour after each vertex */
    vec3 *v;
    int *vline;          /* the line each vertex is on */
    int *fstart, *fline; /* faces: CSR over fvert, and their lines */
    int *fvert;
    int nfvert;
    int cap[5];          /* of v, vline, fstart, fline, fvert */
} Off;

/* room for vertex i and its line number */
static int room_vertex(Off *o, int i)
{
    return vrGrow((void **)&o->v, &o->cap[0], i + 1, sizeof *o->v) != 0
        || vrGrow((void **)&o->vline, &o->cap[1], i + 1, sizeof *o->vline) != 0 ? -1 : 0;
}

/* room for face f's start (and the end after it) and line number */
static int room_face(Off *o, int f)
{
    return vrGrow((void **)&o->fstart, &o->cap[2], f + 2, sizeof *o->fstart) != 0
        || vrGrow((void **)&o->fline, &o->cap[3], f + 1, sizeof *o->fline) != 0 ? -1 : 0;
}

static void off_free(Off *o)
{
    free(o->v);
    free(o->vline);
    free(o->fstart);
    free(o->fline);
    free(o->fvert);
}

/* Splits buf into words in place, dropping a comment; -1 out of memory. */
static int split(Reader *r)
{
    char *s = r->buf, *hash = strchr(s, '#');
    if (hash) *hash = 0;
    r->ntok = 0;
    for (;;) {
        while (*s && isspace((unsigned char)*s)) s++;
        if (!*s) return 0;
        if (vrGrow((void **)&r->tok, &r->captok, r->ntok + 1, sizeof *r->tok) != 0) return -1;
        r->tok[r->ntok++] = s;
        while (*s && !isspace((unsigned char)*s)) s++;
        if (*s) *s++ = 0;
    }
}

/* the next line with a word on it: 1, or 0 at the end of the file, -1 out
 * of memory */
static int next_line(Reader *r)
{
    while (getline(&r->buf, &r->cap, r->f) >= 0) {
        r->line++;
        if (split(r) != 0) return -1;
        if (r->ntok > 0) return 1;
    }
    return 0;
}

/* "path:line: message" */
static int fail_at(const Reader *r, char *err, size_t errlen, const char *what)
{
    return vrGeom_Fail(err, errlen, "%s:%d: %s", r->path, r->line, what);
}

/* the next line with a word on it, which must be there: 0, or -1 saying
 * `what` is missing (or that memory ran out) */
static int need_line(Reader *r, const char *what, char *err, size_t errlen)
{
    int rc = next_line(r);
    if (rc > 0) return 0;
    return rc < 0 ? vrGeom_Fail(err, errlen, "out of memory") : fail_at(r, err, errlen, what);
}

static int parse_int(const char *s, long lo, long hi, int *x)
{
    char *end;
    long v;
    errno = 0;
    v = strtol(s, &end, 10);
    if (end == s || *end || errno || v < lo || v > hi) return -1;
    *x = (int)v;
    return 0;
}

static int parse_double(const char *s, double *x)
{
    char *end;
    *x = strtod(s, &end);
    return end != s && !*end && isfinite(*x) ? 0 : -1;
}

/* the header and the counts; the words after `OFF` are the counts or, when
 * there are none, the next line is */
static int read_header(Reader *r, Off *o, char *err, size_t errlen)
{
    int first = 1, ne;
    char msg[160];
    if (need_line(r, "empty file, expected the header 'OFF' or 'COFF'", err, errlen) != 0) return -1;
    o->coloured = strcmp(r->tok[0], "COFF") == 0;
    if (strcmp(r->tok[0], "OFF") != 0 && !o->coloured) {
        snprintf(msg, sizeof msg, "expected the header 'OFF' or 'COFF', got '%.40s'", r->tok[0]);
        return fail_at(r, err, errlen, msg);
    }
    if (r->ntok == 1) {
        first = 0;
        if (need_line(r, "expected the counts 'vertices faces edges'", err, errlen) != 0) return -1;
    }
    if (r->ntok - first < 2 || r->ntok - first > 3 || parse_int(r->tok[first], 0, OFF_MAX_COUNT, &o->nv) != 0
        || parse_int(r->tok[first + 1], 0, OFF_MAX_COUNT, &o->nf) != 0
        || (r->ntok - first == 3 && parse_int(r->tok[first + 2], 0, 3L * OFF_MAX_COUNT, &ne) != 0))
        return fail_at(r, err, errlen, "expected the counts 'vertices faces edges' (integers >= 0)");
    if (o->nv < 4) {
        snprintf(msg, sizeof msg, "a polyhedron needs at least 4 vertices, the file has %d", o->nv);
        return fail_at(r, err, errlen, msg);
    }
    return 0;   /* the faces are not needed: the hull of the vertices is used */
}

/* reads the next line that `what` (item `index` of `count`) must be on */
static int expect_line(Reader *r, const char *what, int index, int count, char *err, size_t errlen)
{
    char msg[160];
    snprintf(msg, sizeof msg, "unexpected end of file: %s %d of %d is missing", what, index, count);
    return need_line(r, msg, err, errlen);
}

/* OFF: x y z; COFF: x y z and an RGB or RGBA colour */
static int vertex_words_ok(const Off *o, int ntok)
{
    return o->coloured ? ntok == 6 || ntok == 7 : ntok == 3;
}

static int read_vertices(Reader *r, Off *o, char *err, size_t errlen)
{
    char msg[160];
    int i, k;
    for (i = 0; i < o->nv; i++) {
        double x[3];
        if (expect_line(r, "vertex", i, o->nv, err, errlen) != 0) return -1;
        if (room_vertex(o, i) != 0) return vrGeom_Fail(err, errlen, "out of memory");
        if (!vertex_words_ok(o, r->ntok)) {
            snprintf(msg, sizeof msg, "vertex %d: expected 3 coordinates%s, got %d words", i,
                     o->coloured ? " and a colour (r g b or r g b a)" : "", r->ntok);
            return fail_at(r, err, errlen, msg);
        }
        for (k = 0; k < 3; k++)
            if (parse_double(r->tok[k], &x[k]) != 0) {
                snprintf(msg, sizeof msg, "vertex %d: bad coordinate '%.40s' (a finite number is needed)", i,
                         r->tok[k]);
                return fail_at(r, err, errlen, msg);
            }
        o->v[i] = vec3_make(x[0], x[1], x[2]);
        o->vline[i] = r->line;
    }
    return 0;
}

/* one face line: k, then k distinct indices (seen[]: per vertex, the last
 * face that used it), then perhaps a colour */
static int read_face(Reader *r, Off *o, int f, int *seen, char *err, size_t errlen)
{
    char msg[200];
    int k, j, v;
    if (parse_int(r->tok[0], 3, o->nv, &k) != 0) {
        snprintf(msg, sizeof msg, "face %d: bad vertex count '%.40s' (3..%d)", f, r->tok[0], o->nv);
        return fail_at(r, err, errlen, msg);
    }
    if (r->ntok < 1 + k) {
        snprintf(msg, sizeof msg, "face %d: expected %d vertex indices, got %d", f, k, r->ntok - 1);
        return fail_at(r, err, errlen, msg);
    }
    for (j = 1; j <= k; j++) {
        if (parse_int(r->tok[j], 0, o->nv - 1, &v) != 0) {
            snprintf(msg, sizeof msg, "face %d: vertex index '%.40s' is not in 0..%d", f, r->tok[j], o->nv - 1);
            return fail_at(r, err, errlen, msg);
        }
        if (seen[v] == f) {
            snprintf(msg, sizeof msg, "face %d: vertex %d appears twice", f, v);
            return fail_at(r, err, errlen, msg);
        }
        seen[v] = f;
        if (vrGrow((void **)&o->fvert, &o->cap[4], o->nfvert + 1, sizeof *o->fvert) != 0)
            return vrGeom_Fail(err, errlen, "out of memory");
        o->fvert[o->nfvert++] = v;
    }
    return 0;
}

static int read_faces(Reader *r, Off *o, char *err, size_t errlen)
{
    int f, rc = 0, *seen = malloc(sizeof *seen * o->nv); /* the vertices are all read: nv is real */
    if (!seen) rc = vrGeom_Fail(err, errlen, "out of memory");
    /* NOLINTNEXTLINE(clang-analyzer-core.NullDereference): vrGeom_Fail returns -1: rc is set when seen is NULL */
    for (f = 0; rc == 0 && f < o->nv; f++) seen[f] = -1;
    for (f = 0; rc == 0 && f < o->nf; f++) {
        rc = expect_line(r, "face", f, o->nf, err, errlen);
        if (rc == 0 && room_face(o, f) != 0) rc = vrGeom_Fail(err, errlen, "out of memory");
        if (rc == 0) o->fstart[f] = o->nfvert;
        if (rc == 0) rc = read_face(r, o, f, seen, err, errlen);
        if (rc == 0) o->fline[f] = r->line;
    }
    if (rc == 0 && o->nf > 0) o->fstart[o->nf] = o->nfvert;   /* no faces: no array */
    if (rc == 0) {
        int more = next_line(r);
        if (more < 0) rc = vrGeom_Fail(err, errlen, "out of memory");
        if (more > 0) rc = fail_at(r, err, errlen, "unexpected data after the last face");
    }
    free(seen);
    return rc;
}

static int read_off(const char *path, Off *o, char *err, size_t errlen)
{
    Reader r = {0};
    struct stat st;
    int rc;
    r.path = path;
    r.f = fopen(path, "r");
    if (!r.f) return vrGeom_Fail(err, errlen, "%s: cannot open: %s", path, strerror(errno));
    if (fstat(fileno(r.f), &st) == 0 && S_ISDIR(st.st_mode)) {
        rc = vrGeom_Fail(err, errlen, "%s: is a directory", path);
    } else {
        rc = read_header(&r, o, err, errlen);
        if (rc == 0) rc = read_vertices(&r, o, err, errlen);
        if (rc == 0) rc = read_faces(&r, o, err, errlen);
    }
    fclose(r.f);
    free(r.buf);
    free(r.tok);
    return rc;
}

/* ---- the hull of the scaled vertices ---------------------------------------- */

/* the vertices times the scale; a coordinate past VR_LENGTH_MAX is refused
 * at its line, as every other length is */
static int scale_vertices(Off *o, const double scale[3], const char *path, char *err, size_t errlen)
{
    int i;
    for (i = 0; i < o->nv; i++) {
        vec3 x = vec3_make(o->v[i].x * scale[0], o->v[i].y * scale[1], o->v[i].z * scale[2]);
        if (vec3_maxabs(x) > VR_LENGTH_MAX)
            return vrGeom_Fail(err, errlen, "%s:%d: vertex %d is %.3g m from the origin%s (at most %g m)", path,
                               o->vline[i], i, vec3_maxabs(x), scale[0] == 1 && scale[1] == 1 && scale[2] == 1 ? "" : " once scaled",
                               VR_LENGTH_MAX);
        o->v[i] = x;
    }
    return 0;
}

/* "OFF nv 0 0" and the vertices, each coordinate as %.17g: read back, the
 * same doubles, so the same hull */
static char *off_text(const Off *o)
{
    size_t cap = 32 + (size_t)o->nv * 3 * 26, len;
    char *t = malloc(cap);
    int i;
    if (!t) return NULL;
    len = (size_t)snprintf(t, cap, "OFF\n%d 0 0\n", o->nv);
    for (i = 0; i < o->nv; i++)
        len += (size_t)snprintf(t + len, cap - len, "%.17g %.17g %.17g\n", o->v[i].x, o->v[i].y, o->v[i].z);
    return t;
}

static int hull_of(const Off *o, const char *path, vrPolyhedron **out, char *err, size_t errlen)
{
    char msg[200];
    if (vrPolyhedron_HullTol(o->v, o->nv, OFF_TOL, NULL, out, msg, sizeof msg) == 0) return 0;
    return vrGeom_Fail(err, errlen, "%s: %s", path, msg);
}

int vrPolyhedron_FromOFFScaled(const char *path, const double scale[3], vrPolyhedron **out, char **text, char *err,
                               size_t errlen)
{
    Off o = {0};
    int rc;
    *out = NULL;
    if (text) *text = NULL;
    if (!path) return vrGeom_Fail(err, errlen, "no OFF file given");
    rc = read_off(path, &o, err, errlen);
    if (rc == 0) rc = scale_vertices(&o, scale, path, err, errlen);
    if (rc == 0) rc = hull_of(&o, path, out, err, errlen);
    if (rc == 0 && text && !(*text = off_text(&o))) {
        vrPolyhedron_Free(*out);
        *out = NULL;
        rc = vrGeom_Fail(err, errlen, "out of memory");
    }
    off_free(&o);
    return rc;
}

int vrPolyhedron_FromOFF(const char *path, vrPolyhedron **out, char *err, size_t errlen)
{
    static const double unit[3] = {1, 1, 1};
    return vrPolyhedron_FromOFFScaled(path, unit, out, NULL, err, errlen);
}
