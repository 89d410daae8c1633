/* off.c — a convex polyhedron from an OFF file (SPEC 1.1, `polyhedron`).
 *
 * The format (Geomview's OFF): a header line `OFF`, the counts `nv nf [ne]`
 * (on the header line or the next), nv lines `x y z`, nf lines
 * `k i1 .. ik` (a colour may follow the indices: ignored).  `#` starts a
 * comment; blank lines are skipped.
 *
 * The polyhedron is the convex hull of the vertices, and the file must
 * describe that hull: every vertex on the hull's surface and every face in
 * the plane of a hull face, within OFF_TOL of the size.  The tolerance is
 * looser than the hull's own because OFF files are often written with six or
 * seven significant digits; the hull merges its facets at the same one.
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
    if (need_line(r, "empty file, expected the header 'OFF'", err, errlen) != 0) return -1;
    if (strcmp(r->tok[0], "OFF") != 0) {
        snprintf(msg, sizeof msg, "expected the header 'OFF', got '%.40s'", r->tok[0]);
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
    if (o->nf < 4) {
        snprintf(msg, sizeof msg, "a closed polyhedron needs at least 4 faces, the file has %d", o->nf);
        return fail_at(r, err, errlen, msg);
    }
    return 0;
}

/* reads the next line that `what` (item `index` of `count`) must be on */
static int expect_line(Reader *r, const char *what, int index, int count, char *err, size_t errlen)
{
    char msg[160];
    snprintf(msg, sizeof msg, "unexpected end of file: %s %d of %d is missing", what, index, count);
    return need_line(r, msg, err, errlen);
}

static int read_vertices(Reader *r, Off *o, char *err, size_t errlen)
{
    char msg[160];
    int i, k;
    for (i = 0; i < o->nv; i++) {
        double x[3];
        if (expect_line(r, "vertex", i, o->nv, err, errlen) != 0) return -1;
        if (room_vertex(o, i) != 0) return vrGeom_Fail(err, errlen, "out of memory");
        if (r->ntok != 3) {
            snprintf(msg, sizeof msg, "vertex %d: expected 3 coordinates, got %d words", i, r->ntok);
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
    if (rc == 0) o->fstart[o->nf] = o->nfvert;
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

/* ---- convexity ------------------------------------------------------------ */

/* every vertex that is not a hull vertex must lie on the hull's surface */
static int check_vertices(const Off *o, const vrPolyhedron *p, const int *hullv, double tol, const char *path,
                          char *err, size_t errlen)
{
    int i, f;
    for (i = 0; i < o->nv; i++) {
        vec3 x = vec3_sub(o->v[i], p->shift);
        double depth = -INFINITY;
        if (hullv[i] >= 0) continue;
        for (f = 0; f < p->nf; f++)
            if (vrPolyhedron_FaceHeight(p, f, x) > depth) depth = vrPolyhedron_FaceHeight(p, f, x);
        if (depth < -tol)
            return vrGeom_Fail(err, errlen, "%s:%d: not convex (vertex %d lies %.3g inside the hull)", path,
                               o->vline[i], i, -depth);
    }
    return 0;
}

/* the largest distance of OFF face g's vertices from the plane of hull face f */
static double face_gap(const Off *o, const vrPolyhedron *p, int g, int f)
{
    double gap = 0;
    int k;
    for (k = o->fstart[g]; k < o->fstart[g + 1]; k++) {
        double d = fabs(vrPolyhedron_FaceHeight(p, f, vec3_sub(o->v[o->fvert[k]], p->shift)));
        if (d > gap) gap = d;
    }
    return gap;
}

/* the hull face whose plane OFF face g lies nearest: among the faces at one
 * of its hull vertices when it has one, else among all */
static double best_gap(const Off *o, const vrPolyhedron *p, const int *hullv, int g)
{
    int k, hv = -1, f, e, side;
    double best = INFINITY;
    for (k = o->fstart[g]; k < o->fstart[g + 1] && hv < 0; k++) hv = hullv[o->fvert[k]];
    if (hv < 0) {
        for (f = 0; f < p->nf; f++) best = fmin(best, face_gap(o, p, g, f));
        return best;
    }
    for (e = p->vert_edge_start[hv]; e < p->vert_edge_start[hv + 1]; e++)
        for (side = 0; side < 2; side++) best = fmin(best, face_gap(o, p, g, p->edge_f[p->vert_edge[e]][side]));
    return best;
}

static int check_faces(const Off *o, const vrPolyhedron *p, const int *hullv, double tol, const char *path,
                       char *err, size_t errlen)
{
    int g;
    for (g = 0; g < o->nf; g++) {
        double gap = best_gap(o, p, hullv, g);
        if (gap > tol)
            return vrGeom_Fail(err, errlen, "%s:%d: not convex (face %d is not on the hull: "
                               "it is %.3g off the nearest hull face's plane)", path, o->fline[g], g, gap);
    }
    return 0;
}

/* the hull of the vertices, and the check that the file describes it */
static int hull_of(const Off *o, const char *path, vrPolyhedron **out, char *err, size_t errlen)
{
    char msg[200];
    int *src = NULL, *hullv = malloc(sizeof *hullv * o->nv), i, rc;
    double tol = OFF_TOL * vrGeom_Size(o->v, o->nv);
    if (!hullv) return vrGeom_Fail(err, errlen, "out of memory");
    rc = vrPolyhedron_HullTol(o->v, o->nv, OFF_TOL, &src, out, msg, sizeof msg);
    if (rc != 0) {
        free(hullv);
        return vrGeom_Fail(err, errlen, "%s: %s", path, msg);
    }
    for (i = 0; i < o->nv; i++) hullv[i] = -1;
    /* NOLINTNEXTLINE(clang-analyzer-unix.Malloc): a hull has 4 vertices or more (HullTol refuses fewer), so src is not empty */
    for (i = 0; i < (*out)->nv; i++) hullv[src[i]] = i;
    rc = check_vertices(o, *out, hullv, tol, path, err, errlen);
    if (rc == 0) rc = check_faces(o, *out, hullv, tol, path, err, errlen);
    if (rc != 0) {
        vrPolyhedron_Free(*out);
        *out = NULL;
    }
    free(src);
    free(hullv);
    return rc;
}

int vrPolyhedron_FromOFF(const char *path, vrPolyhedron **out, char *err, size_t errlen)
{
    Off o = {0};
    int rc;
    *out = NULL;
    if (!path) return vrGeom_Fail(err, errlen, "no OFF file given");
    rc = read_off(path, &o, err, errlen);
    if (rc == 0) rc = hull_of(&o, path, out, err, errlen);
    off_free(&o);
    return rc;
}
