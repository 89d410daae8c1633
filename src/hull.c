/* hull.c — the convex hull of a point set, as a polyhedron (SPEC 2).
 *
 * Quickhull (Barber, Dobkin & Huhdanpaa 1996, "The Quickhull algorithm for
 * convex hulls"): a triangulated hull whose faces keep the points above them
 * (conflict lists); each step takes a face's farthest point, removes the
 * faces that point sees and cones the horizon to it.  Whether the eye sees a
 * face is decided exactly (Shewchuk 1997, "Adaptive precision floating-point
 * arithmetic and fast robust geometric predicates": a floating-point filter
 * with a proven error bound, then long double, then expansion arithmetic),
 * so the triangulation stays exactly convex and the horizon one cycle
 * whatever duplicates or coplanar clusters come in.  A point within 1e-3 of
 * the tolerance of the hull is dropped (it changes nothing worth a vertex).
 *
 * Then triangles whose corners lie within tol*size of one plane are merged
 * into one polygon face, and the vertices left on fewer than three faces (on
 * an edge or inside a face: not extreme) are dropped; vrPolyhedron_FromFaces
 * builds the graph from the polygons and checks it.  Should points closer
 * than the tolerance make the merge inconsistent, the whole is done again
 * with such points merged first (see vrPolyhedron_HullTol).
 */
#include <float.h>
#include <stdlib.h>
#include <string.h>
#include "grow.h"
#include "polyhedron.h"

/* ---- exact orientation ----------------------------------------------------
 * An expansion is a sum of doubles, ordered by increasing magnitude and
 * non-overlapping (Shewchuk sec. 2); its sign is that of its last term. */
#define EXP_MAX 192 /* the 3x3 determinant of exact differences needs <= 192 terms */

static void two_sum(double a, double b, double *x, double *y)
{
    double s = a + b, bv = s - a, av = s - bv;
    *x = s;
    *y = (a - av) + (b - bv);
}

static void two_product(double a, double b, double *x, double *y)
{
    double p = a * b;
    *x = p;
    *y = fma(a, b, -p); /* the rounding error of a*b, exactly */
}

/* h = e + f (Shewchuk's FAST-EXPANSION-SUM, zeros dropped); returns length */
static int exp_sum(int ne, const double *e, int nf, const double *f, double *h)
{
    double g[EXP_MAX], q, t;
    int i = 0, j = 0, n = 0, k = 0;
    while (i < ne || j < nf) g[n++] = j >= nf || (i < ne && fabs(e[i]) < fabs(f[j])) ? e[i++] : f[j++];
    if (n == 0) {
        h[0] = 0;
        return 1;
    }
    q = g[0];
    for (i = 1; i < n; i++) {
        two_sum(q, g[i], &q, &t);
        if (t != 0) h[k++] = t;
    }
    if (q != 0 || k == 0) h[k++] = q;
    return k;
}

/* h = e * b (Shewchuk's SCALE-EXPANSION, zeros dropped) */
static int exp_scale(int ne, const double *e, double b, double *h)
{
    double q, t, hi, lo, s;
    int i, k = 0;
    two_product(e[0], b, &q, &t);
    if (t != 0) h[k++] = t;
    for (i = 1; i < ne; i++) {
        two_product(e[i], b, &hi, &lo);
        two_sum(q, lo, &s, &t);
        if (t != 0) h[k++] = t;
        two_sum(hi, s, &q, &t);
        if (t != 0) h[k++] = t;
    }
    if (q != 0 || k == 0) h[k++] = q;
    return k;
}

/* h = e * f, f short */
static int exp_mul(int ne, const double *e, int nf, const double *f, double *h)
{
    double part[EXP_MAX], acc[EXP_MAX];
    int n = exp_scale(ne, e, f[0], h), j, m;
    for (j = 1; j < nf; j++) {
        m = exp_scale(ne, e, f[j], part);
        memcpy(acc, h, sizeof *h * n);
        n = exp_sum(n, acc, m, part, h);
    }
    return n;
}

typedef struct Diff { int n; double c[2]; } Diff; /* a - b, exactly */

static Diff exact_diff(double a, double b)
{
    Diff d;
    double x, y;
    two_sum(a, -b, &x, &y);
    d.n = y != 0 ? 2 : 1;
    d.c[0] = y != 0 ? y : x;
    d.c[1] = x;
    return d;
}

/* det[a-p; b-p; c-p], exactly; returns its largest term (its sign is exact) */
static double det_exact(vec3 a, vec3 b, vec3 c, vec3 p)
{
    Diff d[3][3];
    const vec3 *row[3] = {&a, &b, &c};
    double acc[EXP_MAX], old[EXP_MAX];
    int r, i, n = 0;
    for (r = 0; r < 3; r++)
        for (i = 0; i < 3; i++) d[r][i] = exact_diff(vec3_get(*row[r], i), vec3_get(p, i));
    for (i = 0; i < 3; i++) { /* d0_i (d1_j d2_k - d1_k d2_j), (i j k) cyclic */
        int j = (i + 1) % 3, k = (i + 2) % 3, n1, n2, nm, nt, q;
        double m1[8], m2[8], minor[16], term[64];
        n1 = exp_mul(d[1][j].n, d[1][j].c, d[2][k].n, d[2][k].c, m1);
        n2 = exp_mul(d[1][k].n, d[1][k].c, d[2][j].n, d[2][j].c, m2);
        for (q = 0; q < n2; q++) m2[q] = -m2[q];
        nm = exp_sum(n1, m1, n2, m2, minor);
        nt = exp_mul(nm, minor, d[0][i].n, d[0][i].c, term);
        memcpy(old, acc, sizeof *acc * n);
        n = exp_sum(n, old, nt, term, acc);
    }
    return acc[n - 1];
}

/* > 0 when p is above the plane of triangle abc (counter-clockwise seen from
 * above), < 0 below, 0 exactly on it; 6 times the volume of abcp.  First
 * in long double with Shewchuk's error bound (o3derrboundA) for its
 * precision, which settles all but (nearly) exact zeros; those exactly. */
static double orient(vec3 a, vec3 b, vec3 c, vec3 p)
{
    static const long double u = LDBL_EPSILON / 2, bound = (7 + 56 * u) * u;
    long double adx = (long double)a.x - p.x, ady = (long double)a.y - p.y, adz = (long double)a.z - p.z;
    long double bdx = (long double)b.x - p.x, bdy = (long double)b.y - p.y, bdz = (long double)b.z - p.z;
    long double cdx = (long double)c.x - p.x, cdy = (long double)c.y - p.y, cdz = (long double)c.z - p.z;
    long double bc = bdx * cdy, cb = cdx * bdy, ca = cdx * ady, ac = adx * cdy, ab = adx * bdy, ba = bdx * ady;
    long double det = adz * (bc - cb) + bdz * (ca - ac) + cdz * (ab - ba);
    long double perm = (fabsl(bc) + fabsl(cb)) * fabsl(adz) + (fabsl(ca) + fabsl(ac)) * fabsl(bdz)
                     + (fabsl(ab) + fabsl(ba)) * fabsl(cdz);
    if (fabsl(det) > bound * perm) return (double)-det;
    return -det_exact(a, b, c, p);
}

/* ---- quickhull ------------------------------------------------------------ */

/* Failures of one attempt: -1, refused input (or no memory), is final;
 * RETRY, a numerical inconsistency, is tried again with close points merged. */
enum { RETRY = -2 };

typedef struct IntVec { int *a; int n, cap; } IntVec;

enum { FACE_ALIVE, FACE_VISIBLE, FACE_FREE };

typedef struct Face {
    int v[3];        /* counter-clockwise seen from outside */
    int nb[3];       /* nb[i]: the face across the edge v[i] -> v[i+1] */
    int head;        /* first point of its conflict list, -1 if none */
    int far;         /* its farthest conflict point */
    double fardist;  /* orient() of far */
    double minout;   /* orient() of a point drop above it: less is not kept */
    vec3 n, nabs;    /* (v1-v0) x (v2-v0) as computed, and the sums of the
                        magnitudes of its products: the height filter */
    int stamp;       /* the step that last tested it against the eye */
    int state;
} Face;

typedef struct Horizon { int a, b, out; } Horizon; /* edge a->b of a seen face; out: the unseen face */

typedef struct Hull {
    const vec3 *pts;
    int n;
    int *next;       /* conflict lists: the next point above the same face */
    Face *face;
    int nface, capface;
    IntVec freeface, pending, visible, orphans, cone, dfs;
    Horizon *hz;
    int nhz, caphz;
    double drop;     /* points within this of the hull are dropped */
    int step, oom;
} Hull;

static void push(Hull *h, IntVec *v, int x)
{
    if (vrGrow((void **)&v->a, &v->cap, v->n + 1, sizeof *v->a) != 0) {
        h->oom = 1;
        return;
    }
    v->a[v->n++] = x;
}

static void push_horizon(Hull *h, int a, int b, int out)
{
    if (vrGrow((void **)&h->hz, &h->caphz, h->nhz + 1, sizeof *h->hz) != 0) {
        h->oom = 1;
        return;
    }
    h->hz[h->nhz].a = a;
    h->hz[h->nhz].b = b;
    h->hz[h->nhz++].out = out;
}

static void set_plane(Face *f, vec3 a, vec3 b, vec3 c)
{
    vec3 u = vec3_sub(b, a), v = vec3_sub(c, a);
    f->n = vec3_cross(u, v);
    f->nabs = vec3_make(fabs(u.y * v.z) + fabs(u.z * v.y), fabs(u.z * v.x) + fabs(u.x * v.z),
                        fabs(u.x * v.y) + fabs(u.y * v.x));
}

/* a face (a, b, c) with no neighbours yet; -1 when out of memory */
static int new_face(Hull *h, int a, int b, int c)
{
    Face *f;
    int id;
    if (h->freeface.n > 0) {
        id = h->freeface.a[--h->freeface.n];
    } else {
        if (vrGrow((void **)&h->face, &h->capface, h->nface + 1, sizeof *h->face) != 0) {
            h->oom = 1;
            return -1;
        }
        id = h->nface++;
    }
    f = &h->face[id];
    f->v[0] = a;
    f->v[1] = b;
    f->v[2] = c;
    f->nb[0] = f->nb[1] = f->nb[2] = -1;
    f->head = f->far = -1;
    f->fardist = 0;
    set_plane(f, h->pts[a], h->pts[b], h->pts[c]);
    f->minout = h->drop * vec3_len(f->n);
    f->stamp = 0;
    f->state = FACE_ALIVE;
    return id;
}

static double face_orient(const Hull *h, int f, int pt)
{
    const int *v = h->face[f].v;
    return orient(h->pts[v[0]], h->pts[v[1]], h->pts[v[2]], h->pts[pt]);
}

/* n.(p - v0): orient() from the face's stored normal, with *eb bounding its
 * error (each of the eight roundings on the way is at most u relative to
 * the magnitudes summed in nabs.|p - v0|; 16u leaves room) */
static double height(const Hull *h, const Face *F, int pt, double *eb)
{
    vec3 d = vec3_sub(h->pts[pt], h->pts[F->v[0]]);
    *eb = 8 * DBL_EPSILON * (F->nabs.x * fabs(d.x) + F->nabs.y * fabs(d.y) + F->nabs.z * fabs(d.z));
    return vec3_dot(F->n, d);
}

static void add_conflict(Hull *h, int f, int pt, double d)
{
    Face *F = &h->face[f];
    h->next[pt] = F->head;
    F->head = pt;
    if (F->far < 0 || d > F->fardist) {
        F->far = pt;
        F->fardist = d;
    }
}

/* does pt, seen along the normal of face F, fall on its triangle?  A
 * sliver's normal is mostly rounding (its products cancel): no answer */
static int over_triangle(const Hull *h, const Face *F, int pt)
{
    vec3 p = h->pts[pt];
    int i;
    if (vec3_maxabs(F->n) <= 1e-6 * vec3_maxabs(F->nabs)) return 0;
    for (i = 0; i < 3; i++) {
        vec3 a = h->pts[F->v[i]], b = h->pts[F->v[i == 2 ? 0 : i + 1]];
        if (vec3_dot(vec3_cross(vec3_sub(b, a), vec3_sub(p, a)), F->n) < 0) return 0;
    }
    return 1;
}

/* Puts pt in the conflict list of one of faces[0..n) (the new faces of a
 * step, trying faces[*hint] first: neighbouring points share faces) or drops
 * it.  It is dropped when it is above none of them (Barber et al.: then it
 * is inside), or when it lies within drop of one of their triangles (then it
 * is within drop of the hull: a small height alone would not say so, the
 * point may be far out along the face's plane).  So points on a flat within
 * rounding go at once, without exact arithmetic. */
static void assign(Hull *h, int pt, const int *faces, int n, int *hint)
{
    int k, above = -1;
    double dabove = 0;
    for (k = 0; k < n; k++) {
        int at = *hint + k < n ? *hint + k : *hint + k - n, f = faces[at];
        const Face *F = &h->face[f];
        double eb, d = height(h, F, pt, &eb);
        if (d - F->minout > eb) {
            add_conflict(h, f, pt, d);
            *hint = at;
            return;
        }
        if (fabs(d) <= F->minout + eb && over_triangle(h, F, pt)) return;
        if (d > eb && above < 0) {
            above = f;
            dabove = d;
        }
    }
    for (k = 0; k < n && above < 0; k++) { /* the sign too close to call: exactly */
        double eb, d = height(h, &h->face[faces[k]], pt, &eb);
        if (fabs(d) <= eb && face_orient(h, faces[k], pt) > 0) above = faces[k];
    }
    if (above >= 0) add_conflict(h, above, pt, dabove);
}

/* the index of the edge of face f whose neighbour is g */
static int edge_to(const Hull *h, int f, int g)
{
    const int *nb = h->face[f].nb;
    return nb[0] == g ? 0 : nb[1] == g ? 1 : 2;
}

static int sees(Hull *h, int f, int eye)
{
    Face *F = &h->face[f];
    double d, eb;
    if (F->state == FACE_VISIBLE) return 1;
    if (F->stamp == h->step) return 0; /* tested this step: not visible */
    F->stamp = h->step;
    d = height(h, F, eye, &eb);
    if (d > eb || (d >= -eb && face_orient(h, f, eye) > 0)) {
        F->state = FACE_VISIBLE;
        push(h, &h->visible, f);
        return 2; /* newly seen */
    }
    return 0;
}

/* Depth-first over the faces the eye sees, each face's edges taken
 * counter-clockwise from the one it was entered by: the unseen neighbours
 * are met in order round the horizon (as in Lloyd's QuickHull3D). */
static void find_horizon(Hull *h, int f0, int eye)
{
    h->dfs.n = h->nhz = h->visible.n = 0;
    h->face[f0].state = FACE_VISIBLE;
    push(h, &h->visible, f0);
    push(h, &h->dfs, f0);
    push(h, &h->dfs, -1); /* entered by: none, so all three edges */
    push(h, &h->dfs, 0);  /* edges done */
    while (h->dfs.n > 0 && !h->oom) {
        int *fr = &h->dfs.a[h->dfs.n - 3];
        int f = fr[0], entry = fr[1], i, g, seen;
        if (fr[2] == (entry < 0 ? 3 : 2)) {
            h->dfs.n -= 3;
            continue;
        }
        i = entry < 0 ? fr[2] : (entry + 1 + fr[2]) % 3;
        fr[2]++;
        g = h->face[f].nb[i];
        seen = sees(h, g, eye);
        if (seen == 2) {
            push(h, &h->dfs, g);
            push(h, &h->dfs, edge_to(h, g, f));
            push(h, &h->dfs, 0);
        } else if (seen == 0) {
            push_horizon(h, h->face[f].v[i], h->face[f].v[(i + 1) % 3], g);
        }
    }
}

/* the horizon must be one cycle (exact predicates make it so) */
static int horizon_is_cycle(const Hull *h)
{
    int k;
    if (h->nhz < 3) return 0;
    for (k = 0; k < h->nhz; k++)
        if (h->hz[k].b != h->hz[(k + 1) % h->nhz].a) return 0;
    return 1;
}

/* replaces the seen faces with a cone of new faces from the horizon to eye */
static void build_cone(Hull *h, int eye)
{
    int k, j, nh = h->nhz;
    h->cone.n = 0;
    for (k = 0; k < nh; k++) {
        Horizon z = h->hz[k];
        int f = new_face(h, z.a, z.b, eye);
        Face *out;
        if (f < 0) return;
        push(h, &h->cone, f);
        h->face[f].nb[0] = z.out;
        out = &h->face[z.out];
        for (j = 0; j < 3; j++)
            if (out->v[j] == z.b && out->v[(j + 1) % 3] == z.a) out->nb[j] = f;
    }
    if (h->oom) return;
    for (k = 0; k < nh; k++) {
        h->face[h->cone.a[k]].nb[1] = h->cone.a[(k + 1) % nh];
        h->face[h->cone.a[k]].nb[2] = h->cone.a[(k + nh - 1) % nh];
    }
}

/* one quickhull step: the farthest point above face f0 joins the hull;
 * -1 out of memory, RETRY when the horizon is not one cycle */
static int add_point(Hull *h, int f0)
{
    int eye = h->face[f0].far, k, hint = 0;
    h->step++;
    find_horizon(h, f0, eye);
    if (h->oom) return -1;
    if (!horizon_is_cycle(h)) return RETRY;
    h->orphans.n = 0;
    for (k = 0; k < h->visible.n; k++) {
        int f = h->visible.a[k], pt;
        for (pt = h->face[f].head; pt >= 0; pt = h->next[pt])
            if (pt != eye) push(h, &h->orphans, pt);
        h->face[f].state = FACE_FREE;
        push(h, &h->freeface, f);
    }
    build_cone(h, eye);
    if (h->oom) return -1;
    for (k = 0; k < h->orphans.n; k++) assign(h, h->orphans.a[k], h->cone.a, h->cone.n, &hint);
    for (k = 0; k < h->cone.n; k++)
        if (h->face[h->cone.a[k]].head >= 0) push(h, &h->pending, h->cone.a[k]);
    return h->oom ? -1 : 0;
}

/* ---- the first tetrahedron ------------------------------------------------- */

static double dist_to_line(vec3 a, vec3 b, vec3 q)
{
    vec3 d = vec3_sub(b, a);
    return vec3_len(vec3_cross(d, vec3_sub(q, a))) / vec3_len(d);
}

static double dist_to_plane(vec3 a, vec3 b, vec3 c, vec3 q)
{
    vec3 n = vec3_normalize(vec3_cross(vec3_sub(b, a), vec3_sub(c, a)));
    return fabs(vec3_dot(n, vec3_sub(q, a)));
}

/* the two farthest apart of the six axis-extreme points */
static void farthest_pair(const vec3 *p, int n, int *i0, int *i1)
{
    int ext[6] = {0, 0, 0, 0, 0, 0}, i, j, ax;
    double best = -1;
    for (i = 1; i < n; i++)
        for (ax = 0; ax < 3; ax++) {
            if (vec3_get(p[i], ax) < vec3_get(p[ext[2 * ax]], ax)) ext[2 * ax] = i;
            if (vec3_get(p[i], ax) > vec3_get(p[ext[2 * ax + 1]], ax)) ext[2 * ax + 1] = i;
        }
    *i0 = *i1 = 0;
    for (i = 0; i < 6; i++)
        for (j = i + 1; j < 6; j++)
            if (vec3_dist(p[ext[i]], p[ext[j]]) > best) {
                best = vec3_dist(p[ext[i]], p[ext[j]]);
                *i0 = ext[i];
                *i1 = ext[j];
            }
}

static int initial_simplex(Hull *h, double tolabs, char *err, size_t errlen)
{
    /* faces (a b c) (b a d) (c b d) (a c d) and their neighbours, edge by edge */
    static const int nb[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};
    const vec3 *p = h->pts;
    int a, b, c = 0, d = 0, i, f, hint = 0, all[4];
    double best = 0;
    farthest_pair(p, h->n, &a, &b);
    if (!(vec3_dist(p[a], p[b]) > tolabs)) return vrGeom_Fail(err, errlen, "all points coincide");
    for (i = 0; i < h->n; i++) {
        double dl = dist_to_line(p[a], p[b], p[i]);
        if (dl > best) {
            best = dl;
            c = i;
        }
    }
    if (!(best > tolabs)) return vrGeom_Fail(err, errlen, "all points are collinear");
    for (best = 0, i = 0; i < h->n; i++) {
        double dp = dist_to_plane(p[a], p[b], p[c], p[i]);
        if (dp > best) {
            best = dp;
            d = i;
        }
    }
    if (!(best > tolabs)) return vrGeom_Fail(err, errlen, "all points are coplanar (within %g)", tolabs);
    if (orient(p[a], p[b], p[c], p[d]) > 0) { /* d must be below abc */
        i = b;
        b = c;
        c = i;
    }
    all[0] = new_face(h, a, b, c);
    all[1] = new_face(h, b, a, d);
    all[2] = new_face(h, c, b, d);
    all[3] = new_face(h, a, c, d);
    if (h->oom) return vrGeom_Fail(err, errlen, "out of memory");
    for (f = 0; f < 4; f++) memcpy(h->face[all[f]].nb, nb[f], sizeof nb[f]);
    for (i = 0; i < h->n; i++)
        if (i != a && i != b && i != c && i != d) assign(h, i, all, 4, &hint);
    for (f = 0; f < 4; f++)
        if (h->face[f].head >= 0) push(h, &h->pending, f);
    return 0;
}

static void hull_free(Hull *h)
{
    free(h->next);
    free(h->face);
    free(h->freeface.a);
    free(h->pending.a);
    free(h->visible.a);
    free(h->orphans.a);
    free(h->cone.a);
    free(h->dfs.a);
    free(h->hz);
}

static int quickhull(Hull *h, double tolabs, char *err, size_t errlen)
{
    h->next = malloc(sizeof *h->next * h->n);
    if (!h->next) return vrGeom_Fail(err, errlen, "out of memory");
    if (initial_simplex(h, tolabs, err, errlen) != 0) return -1;
    while (h->pending.n > 0) {
        int f = h->pending.a[--h->pending.n], rc;
        if (h->face[f].state != FACE_ALIVE || h->face[f].head < 0) continue;
        rc = add_point(h, f);
        if (rc == -1) return vrGeom_Fail(err, errlen, "out of memory");
        if (rc == RETRY) {
            vrGeom_Fail(err, errlen, "the horizon of point %d is not a cycle", h->face[f].far);
            return RETRY;
        }
    }
    return h->oom ? vrGeom_Fail(err, errlen, "out of memory") : 0;
}

/* ---- merging coplanar triangles into polygons ------------------------------
 * Flood fill from the largest triangle: a neighbour joins when its third
 * corner lies within the tolerance of the seed's plane.  Tolerance is not
 * transitive, so each polygon is then checked: its boundary one simple
 * cycle, the corners it loses (those on fewer than three polygons: inside
 * an edge) within the tolerance of the straight edge that replaces them,
 * and no reflex turn.  A polygon that fails is filled again at the next
 * level, 1000 times tighter, down to exact coplanarity, where the exact
 * convexity of the triangulation makes the checks hold (but for slivers,
 * whose normals are rounding: the RETRY with close points merged). */

enum { EXACT_LEVEL = 3 };
static const double level_scale[EXACT_LEVEL] = {1, 1e-3, 1e-6};

typedef struct Group {
    vec3 n, a;       /* the seed's plane: unit normal, a point */
    int seed, level;
} Group;

typedef struct Tris {
    int n;
    int (*v)[3];
    int (*nb)[3];
    int *group;      /* the polygon each triangle joins, -1: none yet */
    int *level;      /* the level its next polygon is grown at */
    Group *g;
    int ngroup, capgroup;
} Tris;

static void tris_free(Tris *t)
{
    free(t->v);
    free(t->nb);
    free(t->group);
    free(t->level);
    free(t->g);
}

/* the live faces of the quickhull, renumbered 0..n-1 */
static int collect_triangles(const Hull *h, Tris *t)
{
    int *id = malloc(sizeof *id * (h->nface + 1)), f, i;
    t->n = 0;
    if (!id) return -1;
    for (f = 0; f < h->nface; f++) id[f] = h->face[f].state == FACE_ALIVE ? t->n++ : -1;
    t->v = malloc(sizeof *t->v * t->n);
    t->nb = malloc(sizeof *t->nb * t->n);
    t->group = malloc(sizeof *t->group * t->n);
    t->level = calloc(t->n, sizeof *t->level);
    if (!t->v || !t->nb || !t->group || !t->level) {
        free(id);
        return -1;
    }
    for (f = 0; f < h->nface; f++) {
        if (id[f] < 0) continue;
        for (i = 0; i < 3; i++) {
            t->v[id[f]][i] = h->face[f].v[i];
            t->nb[id[f]][i] = id[h->face[f].nb[i]];
        }
        t->group[id[f]] = -1;
    }
    free(id);
    return 0;
}

static vec3 tri_cross(const Tris *t, const vec3 *p, int i)
{
    vec3 a = p[t->v[i][0]];
    return vec3_cross(vec3_sub(p[t->v[i][1]], a), vec3_sub(p[t->v[i][2]], a));
}

/* the triangles, largest first by binary exponent of the area (a counting
 * sort: a seed within a factor 2 of the largest has as good a plane) */
static int *by_area(const Tris *t, const vec3 *p)
{
    enum { NB = 2200, BIAS = 1100 };
    int *count = calloc(NB + 1, sizeof *count), *key = malloc(sizeof *key * (t->n + 1));
    int *order = malloc(sizeof *order * (t->n + 1)), i, b;
    if (!count || !key || !order) {
        free(count);
        free(key);
        free(order);
        return NULL;
    }
    for (i = 0; i < t->n; i++) {
        double a2 = vec3_len2(tri_cross(t, p, i));
        key[i] = a2 > 0 && isfinite(a2) ? NB - 1 - (ilogb(a2) + BIAS) : NB - 1;
        count[key[i] + 1]++;
    }
    for (b = 0; b < NB; b++) count[b + 1] += count[b];
    for (i = 0; i < t->n; i++) order[count[key[i]]++] = i;
    free(count);
    free(key);
    return order;
}

/* is point w on the plane of group g, at g's level? */
static int on_plane(const Tris *t, const vec3 *p, const Group *g, int w, double tolabs)
{
    const int *s = t->v[g->seed];
    if (g->level == EXACT_LEVEL) return orient(p[s[0]], p[s[1]], p[s[2]], p[w]) == 0;
    return fabs(vec3_dot(g->n, vec3_sub(p[w], g->a))) <= tolabs * level_scale[g->level];
}

static int new_group(Tris *t, const vec3 *p, int seed)
{
    Group *g;
    if (vrGrow((void **)&t->g, &t->capgroup, t->ngroup + 1, sizeof *t->g) != 0) return -1;
    g = &t->g[t->ngroup];
    g->n = vec3_normalize(tri_cross(t, p, seed));
    g->a = p[t->v[seed][0]];
    g->seed = seed;
    g->level = t->level[seed];
    return t->ngroup++;
}

static int grow_group(Tris *t, const vec3 *p, int seed, double tolabs, int *queue)
{
    int head = 0, tail = 0, g = new_group(t, p, seed), i;
    if (g < 0) return -1;
    t->group[seed] = g;
    queue[tail++] = seed;
    while (head < tail) {
        int s = queue[head++];
        for (i = 0; i < 3; i++) {
            int u = t->nb[s][i], j;
            if (t->group[u] >= 0 || t->level[u] > t->g[g].level) continue;
            for (j = 0; t->nb[u][j] != s; j++) continue;
            if (on_plane(t, p, &t->g[g], t->v[u][(j + 2) % 3], tolabs)) { /* the corner off the shared edge */
                t->group[u] = g;
                queue[tail++] = u;
            }
        }
    }
    return 0;
}

static int group_triangles(Tris *t, const vec3 *p, const int *order, double tolabs, int *queue)
{
    int k;
    for (k = 0; k < t->n; k++)
        if (t->group[order[k]] < 0 && grow_group(t, p, order[k], tolabs, queue) != 0) return -1;
    return 0;
}

/* Polygon loops: CSR, like the polyhedron's faces; group[f] < 0: dropped */
typedef struct Loops { int n, len, cap, capn; int *start; int *vert; int *group; } Loops;

static int loops_add(Loops *l, int v)
{
    if (vrGrow((void **)&l->vert, &l->cap, l->len + 1, sizeof *l->vert) != 0) return -1;
    l->vert[l->len++] = v;
    return 0;
}

static int close_loop(Loops *l, int g)
{
    if (l->n + 2 > l->capn) {
        int cap = 2 * l->capn + 64;
        int *s = realloc(l->start, sizeof *s * cap), *gr = s ? realloc(l->group, sizeof *gr * cap) : NULL;
        if (s) l->start = s;
        if (!s || !gr) return -1;
        l->group = gr;
        l->capn = cap;
    }
    l->start[l->n + 1] = l->len;
    l->group[l->n++] = g;
    return 0;
}

/* from boundary half-edge (tri, i) of a group, the next one round it: turn
 * about the head vertex through the group's triangles */
static int next_boundary(const Tris *t, int tri, int i)
{
    int g = t->group[tri], e = (i + 1) % 3, guard = 0;
    while (t->group[t->nb[tri][e]] == g && guard++ < t->n) {
        int u = t->nb[tri][e], j;
        for (j = 0; t->nb[u][j] != tri; j++) continue;
        tri = u;
        e = (j + 1) % 3;
    }
    return 3 * tri + e;
}

/* Traces group g's boundary from half-edge first into l: 0 when it is one
 * simple cycle of all its nb boundary half-edges, 1 when not (a hole or a
 * pinch; nothing is added), -1 out of memory.  mark: per vertex, the last
 * group that passed it. */
static int trace_loop(const Tris *t, Loops *l, int first, int nb, int *mark, int g)
{
    int he = first, count = 0, len0 = l->len;
    do {
        int v = t->v[he / 3][he % 3];
        if (mark[v] == g || count == nb) {
            l->len = len0;
            return 1;
        }
        if (loops_add(l, v) != 0) return -1;
        mark[v] = g;
        count++;
        he = next_boundary(t, he / 3, he % 3);
    } while (he != first);
    if (count == nb) return close_loop(l, g);
    l->len = len0;
    return 1;
}

typedef struct Merge {
    Tris *t;
    const vec3 *p;
    int npts;
    double tolabs;
    Loops l;
    int *count;      /* per point: the live loops through it */
    char *dirty;     /* per point: its count changed since loops were checked */
    int *mark;       /* per point: trace_loop's */
    int *loop_of;    /* per group: its loop, -1: none */
    char *bad;       /* per group: to be grown again, tighter */
} Merge;

static void merge_free(Merge *m)
{
    free(m->count);
    free(m->dirty);
    free(m->mark);
    free(m->loop_of);
    free(m->bad);
}

static int merge_alloc(Merge *m)
{
    int i;
    m->count = calloc(m->npts, sizeof *m->count);
    m->dirty = calloc(m->npts, 1);
    m->mark = malloc(sizeof *m->mark * m->npts);
    if (!m->count || !m->dirty || !m->mark) return -1;
    for (i = 0; i < m->npts; i++) m->mark[i] = -1;
    return 0;
}

/* the loops of groups first_new.. (grown this round); a group whose
 * boundary is not one cycle is bad */
static int trace_new(Merge *m, int first_new, int *nbad)
{
    const Tris *t = m->t;
    int n = t->ngroup - first_new, i, g, rc = 0;
    int *first = calloc(n + 1, sizeof *first), *nb = calloc(n + 1, sizeof *nb);
    int *lo = realloc(m->loop_of, sizeof *lo * (t->ngroup + 1));
    char *bad = realloc(m->bad, t->ngroup + 1);
    if (lo) m->loop_of = lo;
    if (bad) m->bad = bad;
    if (!first || !nb || !lo || !bad) rc = -1;
    for (i = 0; rc == 0 && i < 3 * t->n; i++) {
        int gi = t->group[i / 3] - first_new;
        if (gi >= 0 && t->group[t->nb[i / 3][i % 3]] != gi + first_new && nb[gi]++ == 0) first[gi] = i;
    }
    for (g = first_new; rc == 0 && g < t->ngroup; g++) {
        m->loop_of[g] = -1;
        m->bad[g] = 0;
        /* no boundary at all would be a group covering the whole (flat) hull */
        rc = nb[g - first_new] > 0 ? trace_loop(t, &m->l, first[g - first_new], nb[g - first_new], m->mark, g) : 1;
        if (rc == 0) m->loop_of[g] = m->l.n - 1;
        if (rc == 1) {
            m->bad[g] = 1;
            ++*nbad;
            rc = 0;
        }
    }
    free(first);
    free(nb);
    return rc;
}

static int next_kept(const int *vl, int k, const int *count, int i)
{
    do i = i + 1 < k ? i + 1 : 0;
    while (count[vl[i]] < 3);
    return i;
}

/* Does loop vl[0..k) stay a convex polygon within tl when its corners on
 * fewer than three polygons go? */
static int loop_holds(const vec3 *p, const int *vl, int k, const int *count, vec3 n, double tl)
{
    int i, first = -1, kept = 0;
    for (i = 0; i < k; i++)
        if (count[vl[i]] >= 3) {
            if (first < 0) first = i;
            kept++;
        }
    if (kept < 3) return 0;
    i = first;
    do {
        int j = next_kept(vl, k, count, i), c = next_kept(vl, k, count, j), m;
        vec3 a = p[vl[i]], b = p[vl[j]];
        for (m = i + 1 < k ? i + 1 : 0; m != j; m = m + 1 < k ? m + 1 : 0)
            if (dist_to_line(a, b, p[vl[m]]) > tl) return 0;
        if (vec3_dot(vec3_cross(vec3_sub(b, a), vec3_sub(p[vl[c]], b)), n) < -tl * vec3_dist(a, b)) return 0;
        i = j;
    } while (i != first);
    return 1;
}

/* checks the new loops and those through a vertex whose count changed */
static void check_loops(Merge *m, int first_new, int *nbad)
{
    const Loops *l = &m->l;
    int f, i;
    for (f = 0; f < l->n; f++) {
        const Group *g = l->group[f] >= 0 ? &m->t->g[l->group[f]] : NULL;
        int s = l->start[f], k = l->start[f + 1] - s, touched = l->group[f] >= first_new;
        if (!g || g->level == EXACT_LEVEL) continue;
        for (i = 0; i < k && !touched; i++) touched = m->dirty[l->vert[s + i]];
        if (touched && !loop_holds(m->p, l->vert + s, k, m->count, g->n, m->tolabs * level_scale[g->level])) {
            m->bad[l->group[f]] = 1;
            ++*nbad;
        }
    }
}

/* drops the bad groups' loops and frees their triangles for the next level */
static int regrow_bad(Merge *m)
{
    Tris *t = m->t;
    int i, g;
    memset(m->dirty, 0, m->npts);
    for (g = 0; g < t->ngroup; g++) {
        int f = m->loop_of[g];
        if (!m->bad[g] || f < 0) continue;
        for (i = m->l.start[f]; i < m->l.start[f + 1]; i++) {
            m->count[m->l.vert[i]]--;
            m->dirty[m->l.vert[i]] = 1;
        }
        m->l.group[f] = -1;
        m->loop_of[g] = -1;
    }
    for (i = 0; i < t->n; i++) {
        const Group *gr = &t->g[t->group[i]];
        if (!m->bad[t->group[i]]) continue;
        if (gr->level == EXACT_LEVEL) return -2; /* cannot happen with exact signs */
        t->level[i] = gr->level + 1;
        t->group[i] = -1;
    }
    return 0;
}

/* One round: the groups grown since first_new get their loops, the loops
 * they may affect are checked, the bad groups go back to be grown again.
 * *nbad = 0 when the loops are final. */
static int merge_round(Merge *m, int first_new, int *nbad)
{
    int f0 = m->l.n, f, i, rc;
    *nbad = 0;
    rc = trace_new(m, first_new, nbad);
    for (f = f0; rc == 0 && f < m->l.n; f++)
        for (i = m->l.start[f]; i < m->l.start[f + 1]; i++) {
            m->count[m->l.vert[i]]++;
            m->dirty[m->l.vert[i]] = 1;
        }
    if (rc == 0) check_loops(m, first_new, nbad);
    if (rc == 0 && *nbad > 0) rc = regrow_bad(m);
    return rc;
}

/* keeps the live loops only */
static void compact_loops(Loops *l)
{
    int f, i, n = 0, len = 0;
    for (f = 0; f < l->n; f++) {
        int s = l->start[f], e = l->start[f + 1];
        if (l->group[f] < 0) continue;
        l->start[n] = len;
        for (i = s; i < e; i++) l->vert[len++] = l->vert[i];
        l->group[n++] = l->group[f];
    }
    l->n = n;
    l->len = len;
    l->start[n] = len;
}

/* the polygon faces of the triangulated hull, as loops (vertices: point
 * indices, corners that lie on fewer than three polygons still in) */
static int merge_triangles(Merge *m, char *err, size_t errlen)
{
    Tris *t = m->t;
    int *order = by_area(t, m->p), *queue = malloc(sizeof *queue * (t->n + 1)), nbad = 1, rc = 0;
    m->l.capn = 64;
    m->l.start = malloc(sizeof *m->l.start * m->l.capn);
    m->l.group = malloc(sizeof *m->l.group * m->l.capn);
    if (!order || !queue || !m->l.start || !m->l.group || merge_alloc(m) != 0) rc = -1;
    if (rc == 0) m->l.start[0] = 0;
    while (rc == 0 && nbad > 0) {
        int first_new = t->ngroup;
        rc = group_triangles(t, m->p, order, m->tolabs, queue);
        if (rc == 0) rc = merge_round(m, first_new, &nbad);
    }
    if (rc == 0) compact_loops(&m->l);
    free(order);
    free(queue);
    if (rc == -2) {
        vrGeom_Fail(err, errlen, "exactly coplanar faces do not form one polygon");
        return RETRY;
    }
    return rc == 0 ? 0 : vrGeom_Fail(err, errlen, "out of memory");
}

/* Drops the vertices that lie on fewer than three polygons (inside an edge
 * or a face: not extreme) and renumbers the rest 0..nv-1 in input order.
 * keep[] maps input index to new index (-1: dropped). */
static int drop_flat_vertices(Loops *l, int npts, int *keep, int *nv)
{
    int i, f, k = 0, n = 0;
    for (i = 0; i < npts; i++) keep[i] = 0;
    for (i = 0; i < l->len; i++) keep[l->vert[i]]++;
    for (i = 0; i < npts; i++) keep[i] = keep[i] >= 3 ? n++ : -1;
    *nv = n;
    for (f = 0; f < l->n; f++) {
        int s = l->start[f], e = l->start[f + 1];
        l->start[f] = k;
        for (i = s; i < e; i++)
            if (keep[l->vert[i]] >= 0) l->vert[k++] = keep[l->vert[i]];
        if (k - l->start[f] < 3) return -1;
    }
    l->start[l->n] = l->len = k;
    return 0;
}

static int check_points(const vec3 *pts, int n, char *err, size_t errlen)
{
    int i;
    if (!pts || n < 4) return vrGeom_Fail(err, errlen, "a hull needs at least 4 points, got %d", pts ? n : 0);
    for (i = 0; i < n; i++)
        if (!vec3_isfinite(pts[i])) return vrGeom_Fail(err, errlen, "point %d is not finite", i);
    return 0;
}

/* the polygons of the hull and the input index of each vertex (orig maps
 * the points hulled to the input; NULL: the same) */
static int make_polyhedron(const Hull *h, Loops *l, const int *orig, double tol, int **src, vrPolyhedron **out,
                           char *err, size_t errlen)
{
    int *keep = malloc(sizeof *keep * h->n), nv = 0, i, rc = RETRY;
    vec3 *v = malloc(sizeof *v * h->n);
    int *map = malloc(sizeof *map * h->n);
    if (!keep || !v || !map) {
        rc = vrGeom_Fail(err, errlen, "out of memory");
    } else if (drop_flat_vertices(l, h->n, keep, &nv) != 0) {
        vrGeom_Fail(err, errlen, "a merged face lost its corners");
    } else {
        for (i = 0; i < h->n; i++)
            if (keep[i] >= 0) {
                v[keep[i]] = h->pts[i];
                map[keep[i]] = orig ? orig[i] : i;
            }
        if (vrPolyhedron_FromFaces(v, nv, l->start, l->vert, l->n, tol, out, err, errlen) == 0) rc = 0;
    }
    if (rc == 0 && src) {
        *src = map;
        map = NULL;
    }
    free(keep);
    free(v);
    free(map);
    return rc;
}

/* one attempt over the points pts[0..n) (orig: their input indices) */
static int hull_attempt(const vec3 *pts, int n, const int *orig, double tol, double tolabs, int **src,
                        vrPolyhedron **out, char *err, size_t errlen)
{
    Hull h;
    Tris t = {0};
    Merge m = {0};
    int rc;
    memset(&h, 0, sizeof h);
    h.pts = pts;
    h.n = n;
    h.drop = 1e-3 * tolabs;
    m.t = &t;
    m.p = pts;
    m.npts = n;
    m.tolabs = tolabs;
    rc = quickhull(&h, tolabs, err, errlen);
    if (rc == 0 && collect_triangles(&h, &t) != 0) rc = vrGeom_Fail(err, errlen, "out of memory");
    if (rc == 0) rc = merge_triangles(&m, err, errlen);
    if (rc == 0) rc = make_polyhedron(&h, &m.l, orig, tol, src, out, err, errlen);
    hull_free(&h);
    tris_free(&t);
    merge_free(&m);
    free(m.l.start);
    free(m.l.vert);
    free(m.l.group);
    return rc;
}

/* ---- merging points closer than r (the retries) ---------------------------- */

typedef struct Grid {  /* cells of side r, hashed; each lists its representatives */
    long long (*key)[3];
    int *head, *link;
    int cap;
    vec3 lo;
    double r;
} Grid;

static void cell_of(const Grid *g, vec3 p, long long c[3])
{
    c[0] = (long long)floor((p.x - g->lo.x) / g->r);
    c[1] = (long long)floor((p.y - g->lo.y) / g->r);
    c[2] = (long long)floor((p.z - g->lo.z) / g->r);
}

/* the slot of cell c: where it is, or the empty one where it would go */
static int grid_slot(const Grid *g, const long long c[3])
{
    unsigned long long hsh = (unsigned long long)c[0] * 0x9E3779B97F4A7C15ULL
                           ^ (unsigned long long)c[1] * 0xC2B2AE3D27D4EB4FULL
                           ^ (unsigned long long)c[2] * 0x165667B19E3779F9ULL;
    int s = (int)((hsh ^ (hsh >> 29)) & (unsigned long long)(g->cap - 1));
    while (g->head[s] >= 0 && memcmp(g->key[s], c, sizeof g->key[s]) != 0) s = (s + 1) & (g->cap - 1);
    return s;
}

/* an earlier representative within r of p, or -1 */
static int grid_near(const Grid *g, const vec3 *pts, vec3 p)
{
    long long c[3], d[3];
    int i, j;
    cell_of(g, p, c);
    for (i = 0; i < 27; i++) {
        int s;
        d[0] = c[0] + i % 3 - 1;
        d[1] = c[1] + i / 3 % 3 - 1;
        d[2] = c[2] + i / 9 - 1;
        s = grid_slot(g, d);
        for (j = g->head[s]; j >= 0; j = g->link[j])
            if (vec3_dist(pts[j], p) <= g->r) return j;
    }
    return -1;
}

static void grid_free(Grid *g)
{
    free(g->key);
    free(g->head);
    free(g->link);
}

static int grid_alloc(Grid *g, const vec3 *pts, int n, double r)
{
    int i;
    g->cap = 1;
    while (g->cap < 2 * n) g->cap <<= 1;
    g->key = malloc(sizeof *g->key * g->cap);
    g->head = malloc(sizeof *g->head * g->cap);
    g->link = malloc(sizeof *g->link * n);
    if (!g->key || !g->head || !g->link) return -1;
    for (i = 0; i < g->cap; i++) g->head[i] = -1;
    g->r = r;
    g->lo = pts[0];
    for (i = 1; i < n; i++)
        g->lo = vec3_min(g->lo, pts[i]);
    return 0;
}

/* Each point goes to the first earlier representative within r, or
 * becomes one: rep[0..*m) lists the representatives, in input order. */
static int snap_points(const vec3 *pts, int n, double r, int *rep, int *m)
{
    Grid g = {0};
    int i;
    *m = 0;
    if (grid_alloc(&g, pts, n, r) != 0) {
        grid_free(&g);
        return -1;
    }
    for (i = 0; i < n; i++) {
        long long c[3];
        int s;
        if (grid_near(&g, pts, pts[i]) >= 0) continue;
        cell_of(&g, pts[i], c);
        s = grid_slot(&g, c);
        memcpy(g.key[s], c, sizeof c);
        g.link[i] = g.head[s];
        g.head[s] = i;
        rep[(*m)++] = i;
    }
    grid_free(&g);
    return 0;
}

/* the attempt with the points closer than r merged into the first of them */
static int snapped_attempt(const vec3 *pts, int n, double r, double tol, double tolabs, int **src,
                           vrPolyhedron **out, char *err, size_t errlen)
{
    int *rep = malloc(sizeof *rep * n), m = 0, i, rc;
    vec3 *q = malloc(sizeof *q * n);
    if (!rep || !q || snap_points(pts, n, r, rep, &m) != 0) {
        rc = vrGeom_Fail(err, errlen, "out of memory");
    } else {
        for (i = 0; i < m; i++) q[i] = pts[rep[i]];
        rc = m < 4 ? RETRY : hull_attempt(q, m, rep, tol, tolabs, src, out, err, errlen);
    }
    free(rep);
    free(q);
    return rc;
}

int vrPolyhedron_HullTol(const vec3 *pts, int n, double tol, int **src, vrPolyhedron **out, char *err,
                         size_t errlen)
{
    /* a triangulation exact for points closer than the tolerance may not
     * merge consistently (slivers, corners blurred at the tolerance's
     * scale): then such points are merged, at growing distances */
    static const double snap[] = {0, 1, 10, 100, 1000};
    double tolabs;
    int k, rc;
    char why[256] = "";
    *out = NULL;
    if (src) *src = NULL;
    if (check_points(pts, n, err, errlen) != 0) return -1;
    tolabs = tol * vrGeom_Size(pts, n);
    rc = hull_attempt(pts, n, NULL, tol, tolabs, src, out, why, sizeof why);
    for (k = 1; rc == RETRY && k < 5; k++)
        rc = snapped_attempt(pts, n, snap[k] * tolabs, tol, tolabs, src, out, why, sizeof why);
    if (rc == RETRY)
        return vrGeom_Fail(err, errlen, "hull: numerically inconsistent (%s) even with points within %g merged", why,
                           snap[4] * tolabs);
    if (rc != 0) return vrGeom_Fail(err, errlen, "%s", why);
    return 0;
}

int vrPolyhedron_Hull(const vec3 *pts, int n, vrPolyhedron **out, char *err, size_t errlen)
{
    return vrPolyhedron_HullTol(pts, n, VR_COPLANAR_TOL, NULL, out, err, errlen);
}
