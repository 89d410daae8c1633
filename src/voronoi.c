/* voronoi.c — the Voronoi regions of a convex polyhedron's features (V-Clip,
 * Mirtich 1998, sec. 3), what the closest-feature walk (closest.c) moves by.
 *
 * A feature (vertex, edge, face) owns a region bounded by planes, each plane
 * naming the neighbouring feature that lies beyond it.  The planes are not
 * stored: they are computed on the fly from the stored geometry (a few flops
 * each), in the body frame of the polyhedron.
 *   consider                 one plane's excess against the worst so far
 *   vertex_region,           the planes of a vertex, an edge, a face
 *   edge_region, face_region
 *   face_plane               a face's FE plane through one of its edges
 *   vrVoronoi_HighestFace,   the face planes' search, a feature's closest
 *   vrVoronoi_ClosestOnFeature  point (the walks' ends, closest*.c)
 */
#include "segment.h"
#include "voronoi.h"

/* Each region is bounded by planes, each naming the neighbour feature that
 * lies beyond it.  A test returns the plane x violates most, by its excess
 * in metres (s / |nrm| for a plane nrm.(x - o) <= 0), ignoring excesses up
 * to tol: leaving through the worst plane never increases the distance
 * (Mirtich sec. 5.2).  Planes are evaluated from the stored geometry, in
 * the form that costs fewest flops. */
typedef struct Worst { double score, slack2; vrFeature nbr; int found; } Worst;

/* plane excess s / sqrt(l2) against the worst so far; slack2 keeps the
 * square of the largest excess let pass as within tol */
static inline void consider(Worst *w, double s, double l2, double tol, int type, int index)
{
    if (s <= 0) return;
    if (s * s <= tol * tol * l2) {
        if (s * s > w->slack2 * l2) w->slack2 = s * s / l2;
        return;
    }
    if (w->found && s * s <= w->score * l2) return;
    w->score = s * s / l2;
    w->nbr.type = type;
    w->nbr.index = index;
    w->found = 1;
}

/* vertex: per incident edge, the plane through v perpendicular to it */
static void vertex_region(const vrPolyhedron *p, int v, vec3 x, double tol, Worst *w)
{
    vec3 r = vec3_sub(x, p->vert[v]);
    int k;
    for (k = p->vert_edge_start[v]; k < p->vert_edge_start[v + 1]; k++) {
        int e = p->vert_edge[k];
        vec3 d = vec3_sub(p->vert[vrPolyhedron_OtherEnd(p, e, v)], p->vert[v]);
        consider(w, vec3_dot(r, d), vec3_len2(d), tol, VR_EDGE, e);
    }
}

/* edge t->h: the planes through t and h perpendicular to it (beyond: those
 * vertices), then those holding it and the left / right face normal
 * (beyond: those faces).  The vertex planes come first: leaving through one
 * keeps the distance, while a face plane violated near an end might not
 * lower it.  With d in the faces, |n x d| = |d|, and
 * (x - t).(n x d) = n.(d x (x - t)). */
static void edge_region(const vrPolyhedron *p, int e, vec3 x, double tol, Worst *w)
{
    const int *ev = p->edge_v[e], *ef = p->edge_f[e];
    vec3 t = p->vert[ev[0]], d = vec3_sub(p->vert[ev[1]], t), r = vec3_sub(x, t), c;
    double u = vec3_dot(r, d), l2 = vec3_len2(d);
    consider(w, -u, l2, tol, VR_VERTEX, ev[0]);
    consider(w, u - l2, l2, tol, VR_VERTEX, ev[1]);
    if (w->found) return;
    c = vec3_cross(d, r);
    consider(w, vec3_dot(p->face_normal[ef[0]], c), l2, tol, VR_FACE, ef[0]); /* n_l x d points into the left face */
    consider(w, -vec3_dot(p->face_normal[ef[1]], c), l2, tol, VR_FACE, ef[1]);
}

/* face: per boundary edge a->b, the plane holding it and the normal
 * (beyond: that edge); its outward normal is (b - a) x n, so the excess is
 * n.((x - a) x (b - a)).  The face plane itself is the walk's business. */
static void face_region(const vrPolyhedron *p, int f, vec3 x, double tol, Worst *w)
{
    int k, s = p->face_start[f], m = p->face_start[f + 1] - s;
    vec3 n = p->face_normal[f];
    for (k = 0; k < m; k++) {
        vec3 a = p->vert[p->face_vert[s + k]], d = vec3_sub(p->vert[p->face_vert[s + (k + 1 == m ? 0 : k + 1)]], a);
        consider(w, vec3_dot(n, vec3_cross(vec3_sub(x, a), d)), vec3_len2(d), tol, VR_EDGE, p->face_edge[s + k]);
    }
}

int vrVoronoi_Violation(const vrPolyhedron *p, vrFeature f, vec3 x, double tol, vrFeature *nbr, double *slack2)
{
    Worst w;
    w.found = 0;
    w.score = w.slack2 = 0;
    if (f.type == VR_VERTEX) vertex_region(p, f.index, x, tol, &w);
    else if (f.type == VR_EDGE) edge_region(p, f.index, x, tol, &w);
    else face_region(p, f.index, x, tol, &w);
    if (w.found) *nbr = w.nbr;
    else if (slack2 && w.slack2 > *slack2) *slack2 = w.slack2;
    return w.found;
}

/* the FE plane of face f's boundary edge k as nrm.x <= off (for clipping) */
typedef struct Plane { vec3 nrm; double off; } Plane;

static Plane face_plane(const vrPolyhedron *p, int f, int k)
{
    Plane pl;
    int s = p->face_start[f], m = p->face_start[f + 1] - s;
    vec3 a = p->vert[p->face_vert[s + k]], b = p->vert[p->face_vert[s + (k + 1 == m ? 0 : k + 1)]];
    pl.nrm = vec3_cross(vec3_sub(b, a), p->face_normal[f]);
    pl.off = vec3_dot(pl.nrm, a);
    return pl;
}

/* Mirtich's clipping, sec. 4 */
int vrVoronoi_ClipToFace(const vrPolyhedron *p, int f, vec3 t, vec3 h, double *lo, double *hi)
{
    int k, n = vrPolyhedron_FaceSize(p, f);
    *lo = 0;
    *hi = 1;
    for (k = 0; k < n; k++) {
        Plane pl = face_plane(p, f, k);
        double st = vec3_dot(pl.nrm, t) - pl.off, sh = vec3_dot(pl.nrm, h) - pl.off;
        if (st > 0 && sh > 0) return 0;
        if (st > 0) {
            double lam = st / (st - sh);
            if (lam > *lo) *lo = lam;
        } else if (sh > 0) {
            double lam = st / (st - sh);
            if (lam < *hi) *hi = lam;
        }
        if (*lo > *hi) return 0;
    }
    return 1;
}

int vrVoronoi_InPrism(const vrPolyhedron *p, int f, vec3 x)
{
    int k, n = vrPolyhedron_FaceSize(p, f);
    for (k = 0; k < n; k++) {
        Plane pl = face_plane(p, f, k);
        if (vec3_dot(pl.nrm, x) > pl.off) return 0;
    }
    return 1;
}

int vrVoronoi_HighestFace(const vrPolyhedron *p, vec3 x, double *height)
{
    int g, best = 0;
    double smax = -HUGE_VAL;
    for (g = 0; g < p->nf; g++) {
        double s = vrPolyhedron_FaceHeight(p, g, x);
        if (s > smax) {
            smax = s;
            best = g;
        }
    }
    *height = smax;
    return best;
}

vec3 vrVoronoi_ClosestOnFeature(const vrPolyhedron *p, vrFeature f, vec3 x)
{
    if (f.type == VR_VERTEX) return p->vert[f.index];
    if (f.type == VR_EDGE) {
        vec3 t = p->vert[p->edge_v[f.index][0]], h = p->vert[p->edge_v[f.index][1]];
        return vec3_lerp(t, h, vrSegment_PointParam(t, h, x));
    }
    return vec3_madd(x, -vrPolyhedron_FaceHeight(p, f.index, x), p->face_normal[f.index]);
}
