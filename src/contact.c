/* contact.c — canonical distance, normal and contact region of a posed pair
 * (SPEC 2 "Contact region", SPEC 3.2 determinism rules, thesis 3.2.1).
 *
 * The walk (closest.c) only finds A closest feature pair.  When faces are
 * parallel many pairs are equally closest (a box flat on a table: vertex-
 * face, edge-face, face-face), and which one the walk ends on depends on
 * where its cache started.  So nothing here is taken from the walk's result
 * but a direction: from it we build each body's near-support set (vertices
 * within SUPPORT_TOL of the supporting plane), classify it as a vertex, an
 * edge or a face, and compute distance, normal, closest points and region
 * from those features and the poses alone, by fixed formulas:
 *   a's face -> its normal;  else b's face -> minus its normal;
 *   edge x edge (not parallel) -> the cross product;
 *   otherwise the closest points of the two features.
 * The result is a pure function of (shapes, poses): the cache buys speed
 * only.  (Left to chance: a set member within rounding of the 1e-9 m
 * threshold.  Whether a contact within rounding of distance 0 counts as
 * touching or overlapping is decided by a walk from a fixed start:
 * TOUCH_TOL.)
 *
 * Spheres collide as true spheres: closed forms against spheres and boxes
 * (thesis 3.2.1 [Glassner90]), the walk to the centre against any other
 * polyhedron; their depths are exact.  Overlapping polyhedra go to libccd
 * (penetration.c).
 *
 * No static state; scratch memory lives on the stack unless a set outgrows
 * its inline buffer.
 */
#include <stdlib.h>
#include <string.h>

#include "contact.h"
#include "segment.h"

#define SUPPORT_TOL 1e-9   /* tau: near-support set tolerance (m) */
#define REGION_SLACK 1e-9  /* slab slack and 2D containment tolerance (m) */
#define DEDUP_EPS 1e-12    /* region points closer than this are one (m) */
#define PARALLEL_SIN2 1e-12

/* ---- small sets of vertex indices ------------------------------------- */

typedef struct IntSet { int n, cap; int *v; int buf[32]; } IntSet;

static void set_init(IntSet *s)
{
    s->n = 0;
    s->cap = (int)(sizeof s->buf / sizeof s->buf[0]);
    s->v = s->buf;
}

static void set_free(IntSet *s)
{
    if (s->v != s->buf) free(s->v);
    set_init(s);
}

static int set_has(const IntSet *s, int x)
{
    int i;
    for (i = 0; i < s->n; i++)
        if (s->v[i] == x) return 1;
    return 0;
}

static int set_add(IntSet *s, int x)
{
    if (s->n == s->cap) {
        int *v = malloc(2 * (size_t)s->cap * sizeof *v);
        if (!v) return -1;
        memcpy(v, s->v, (size_t)s->n * sizeof *v);
        if (s->v != s->buf) free(s->v);
        s->v = v;
        s->cap *= 2;
    }
    s->v[s->n++] = x;
    return 0;
}

static void set_sort(IntSet *s)
{
    int i, j;
    for (i = 1; i < s->n; i++) {
        int x = s->v[i];
        for (j = i; j > 0 && s->v[j - 1] > x; j--) s->v[j] = s->v[j - 1];
        s->v[j] = x;
    }
}

/* ---- a posed polyhedron -------------------------------------------------- */

typedef struct Body { const vrPolyhedron *p; const vrPose *pose; } Body;

static vec3 world_vert(const Body *b, int i) { return vrPose_apply(b->pose, b->p->vert[i]); }

/* Breadth-first search from `seed` over the vertices with d.v >= floor (body
 * frame).  On a convex polytope this set is connected whenever it holds the
 * top vertex: every other vertex has a higher neighbour. */
static int collect(const vrPolyhedron *p, vec3 d, int seed, double floor, IntSet *out)
{
    int i, k;
    if (set_add(out, seed)) return -1;
    for (i = 0; i < out->n; i++) {
        int v = out->v[i];
        for (k = p->vert_edge_start[v]; k < p->vert_edge_start[v + 1]; k++) {
            int w = vrPolyhedron_OtherEnd(p, p->vert_edge[k], v);
            if (vec3_dot(d, p->vert[w]) >= floor && !set_has(out, w) && set_add(out, w)) return -1;
        }
    }
    return 0;
}

/* The near-support set of b in world direction dir: the vertices within
 * SUPPORT_TOL of the highest, ascending.  The filter after the search makes
 * the set independent of which top vertex the climb reached. */
static int support_set(const Body *b, vec3 dir, int start, IntSet *out)
{
    vec3 d = mat33_tmulv(&b->pose->R, dir);
    double top, gap;
    int v = vrPolyhedron_Climb(b->p, d, start, &gap), i, n = 0;
    if (gap > SUPPORT_TOL) return set_add(out, v); /* a lone top vertex: the common case */
    if (collect(b->p, d, v, vec3_dot(d, b->p->vert[v]) - SUPPORT_TOL, out)) return -1;
    top = vec3_dot(d, b->p->vert[out->v[0]]);
    for (i = 1; i < out->n; i++)
        if (vec3_dot(d, b->p->vert[out->v[i]]) > top) top = vec3_dot(d, b->p->vert[out->v[i]]);
    for (i = 0; i < out->n; i++)
        if (vec3_dot(d, b->p->vert[out->v[i]]) >= top - SUPPORT_TOL) out->v[n++] = out->v[i];
    out->n = n;
    set_sort(out);
    return 0;
}

/* ---- support features ----------------------------------------------------- */

typedef struct Support {
    int kind, index;   /* VR_VERTEX / VR_EDGE / VR_FACE and its index */
    IntSet v;          /* its vertices, ascending */
} Support;

static int edge_between(const vrPolyhedron *p, int v, int w)
{
    int k;
    for (k = p->vert_edge_start[v]; k < p->vert_edge_start[v + 1]; k++)
        if (vrPolyhedron_OtherEnd(p, p->vert_edge[k], v) == w) return p->vert_edge[k];
    return -1;
}

static int face_within(const vrPolyhedron *p, int f, const IntSet *s)
{
    int k;
    for (k = p->face_start[f]; k < p->face_start[f + 1]; k++)
        if (!set_has(s, p->face_vert[k])) return 0;
    return 1;
}

/* the face around s's vertices whose vertices all lie in s: an exact match
 * if there is one, else the one facing d best (lowest index on ties); -1 if none */
static int face_of_set(const vrPolyhedron *p, vec3 d, const IntSet *s)
{
    int i, k, j, best = -1;
    double bestv = -HUGE_VAL;
    for (i = 0; i < s->n; i++)
        for (k = p->vert_edge_start[s->v[i]]; k < p->vert_edge_start[s->v[i] + 1]; k++)
            for (j = 0; j < 2; j++) {
                int f = p->edge_f[p->vert_edge[k]][j];
                double fv = vec3_dot(d, p->face_normal[f]);
                if (!face_within(p, f, s)) continue;
                if (vrPolyhedron_FaceSize(p, f) == s->n) return f;
                if (fv > bestv || (fv == bestv && f < best)) bestv = fv, best = f;
            }
    return best;
}

static int set_to_face(const vrPolyhedron *p, int f, IntSet *s)
{
    int k;
    s->n = 0;
    for (k = p->face_start[f]; k < p->face_start[f + 1]; k++)
        if (set_add(s, p->face_vert[k])) return -1;
    set_sort(s);
    return 0;
}

/* Does body-frame direction d have exactly face f's vertices as its
 * near-support set?  Yes when d is so near f's normal that, with the face's
 * spread, they stay within SUPPORT_TOL of one another and every other vertex
 * stays more than SUPPORT_TOL below them (rounding allowed for): then the
 * search below would find f, so it need not run. */
static int face_is_support(const vrPolyhedron *p, vec3 d, int f)
{
    double slack = 2 * (vec3_dist(d, p->face_normal[f]) + 1e-12) * p->r_out + 1e-12;
    return p->face_spread[f] + slack < SUPPORT_TOL && p->face_drop[f] - slack > SUPPORT_TOL;
}

/* The support feature of b along world dir (Mirtich's features), searched
 * from the walk's feature `from`: 1 vertex, 2 = an edge, >= 3 = a face.
 * Sets that are none of these (tolerance corner cases) fall back to a face
 * inside the set, or to its highest vertex.  When the walk ended on a face
 * that is the support (a box on a table), it is taken at once. */
static int support_feature(const Body *b, vec3 dir, vrFeature from, Support *s)
{
    const vrPolyhedron *p = b->p;
    vec3 d = mat33_tmulv(&b->pose->R, dir);
    if (from.type == VR_FACE && from.index >= 0 && from.index < p->nf && face_is_support(p, d, from.index)) {
        s->kind = VR_FACE;
        s->index = from.index;
        return set_to_face(p, s->index, &s->v);
    }
    if (support_set(b, dir, vrFeature_Vertex(p, from), &s->v)) return -1;
    if (s->v.n == 2 && (s->index = edge_between(p, s->v.v[0], s->v.v[1])) >= 0) {
        s->kind = VR_EDGE;
        return 0;
    }
    if (s->v.n >= 3 && (s->index = face_of_set(p, d, &s->v)) >= 0) {
        s->kind = VR_FACE;
        return set_to_face(p, s->index, &s->v);
    }
    s->kind = VR_VERTEX;
    s->index = s->v.n == 1 ? s->v.v[0] : vrPolyhedron_Climb(p, d, s->v.v[0], NULL);
    s->v.n = 0;
    return set_add(&s->v, s->index);
}

/* ---- canonical distance and normal ---------------------------------------- */

typedef struct Canon {
    Support sa, sb;
    vec3 n;          /* world, from a toward b */
    double dist;
    vec3 qa, qb;     /* closest points (canonical choice on ties) */
    double ha, hb;   /* support planes n.x = ha (of a) and n.x = hb (of b) */
} Canon;

static void canon_init(Canon *c)
{
    set_init(&c->sa.v);
    set_init(&c->sb.v);
}

static void canon_free(Canon *c)
{
    set_free(&c->sa.v);
    set_free(&c->sb.v);
}

/* world plane n.x = h of face f */
static vec3 face_plane(const Body *b, int f, double *h)
{
    vec3 n = vrPose_rotate(b->pose, b->p->face_normal[f]);
    *h = b->p->face_offset[f] + vec3_dot(n, b->pose->p);
    return n;
}

static double min_height(const Body *b, const IntSet *s, vec3 n)
{
    double m = HUGE_VAL;
    int i;
    for (i = 0; i < s->n; i++) {
        double h = vec3_dot(n, world_vert(b, s->v[i]));
        if (h < m) m = h;
    }
    return m;
}

static vec3 centroid(const Body *b, const IntSet *s)
{
    vec3 c = vec3_zero();
    int i;
    for (i = 0; i < s->n; i++) c = vec3_add(c, world_vert(b, s->v[i]));
    return vec3_scale(c, 1.0 / s->n);
}

/* a face of `fb` (world plane n.x = h) against the support set of `other`:
 * distance from the lowest vertex, closest points from the set's centroid */
static double face_against(const Body *other, const IntSet *s, vec3 n, double h, vec3 *q_face, vec3 *q_other)
{
    double dist = min_height(other, s, n) - h;
    *q_other = centroid(other, s);
    *q_face = vec3_madd(*q_other, -(vec3_dot(n, *q_other) - h), n);
    return dist;
}

/* end points of a vertex or edge support feature, world (a vertex twice) */
static void feature_segment(const Body *b, const Support *s, vec3 *p0, vec3 *p1)
{
    int t = s->kind == VR_EDGE ? b->p->edge_v[s->index][0] : s->index;
    int h = s->kind == VR_EDGE ? b->p->edge_v[s->index][1] : s->index;
    *p0 = world_vert(b, t);
    *p1 = world_vert(b, h);
}

/* edge x edge: n = normalised cross product of the stored edges, pointing
 * from a's centre side to b's; 0 when the edges are parallel */
static int edge_edge_normal(const Body *a, const Body *b, Canon *c)
{
    vec3 a0, a1, b0, b1, ea, eb, n;
    double s, t;
    feature_segment(a, &c->sa, &a0, &a1);
    feature_segment(b, &c->sb, &b0, &b1);
    ea = vec3_sub(a1, a0);
    eb = vec3_sub(b1, b0);
    n = vec3_cross(ea, eb);
    if (vec3_len2(n) <= PARALLEL_SIN2 * vec3_len2(ea) * vec3_len2(eb)) return 0;
    n = vec3_normalize(n);
    if (vec3_dot(n, vec3_sub(b->pose->p, a->pose->p)) < 0) n = vec3_neg(n);
    c->n = n;
    c->ha = vec3_dot(n, a0);
    c->hb = vec3_dot(n, b0);
    c->dist = c->hb - c->ha;
    vrSegment_ClosestParams(a0, a1, b0, b1, &s, &t);
    c->qa = vec3_lerp(a0, a1, s);
    c->qb = vec3_lerp(b0, b1, t);
    return 1;
}

/* vertex / edge combinations and parallel edges: the closest points of the
 * two features by the fixed segment formula */
static void point_features(const Body *a, const Body *b, Canon *c)
{
    vec3 a0, a1, b0, b1;
    double s, t;
    feature_segment(a, &c->sa, &a0, &a1);
    feature_segment(b, &c->sb, &b0, &b1);
    vrSegment_ClosestParams(a0, a1, b0, b1, &s, &t);
    c->qa = vec3_lerp(a0, a1, s);
    c->qb = vec3_lerp(b0, b1, t);
    c->dist = vec3_dist(c->qa, c->qb);
    c->n = vec3_normalize(vec3_sub(c->qb, c->qa));
    c->ha = -min_height(a, &c->sa.v, vec3_neg(c->n));
    c->hb = min_height(b, &c->sb.v, c->n);
}

/* Steps 2-4 of the rule: support features along dir (a) and -dir (b),
 * then normal and distance from them. */
static int canonical(const Body *a, const Body *b, vec3 dir, vrFeature fa, vrFeature fb, Canon *c)
{
    if (support_feature(a, dir, fa, &c->sa) || support_feature(b, vec3_neg(dir), fb, &c->sb)) return -1;
    if (c->sa.kind == VR_FACE) {
        c->n = face_plane(a, c->sa.index, &c->ha);
        c->dist = face_against(b, &c->sb.v, c->n, c->ha, &c->qa, &c->qb);
        c->hb = c->ha + c->dist;
    } else if (c->sb.kind == VR_FACE) {
        double hf;
        vec3 nb = face_plane(b, c->sb.index, &hf);
        c->dist = face_against(a, &c->sa.v, nb, hf, &c->qb, &c->qa);
        c->n = vec3_neg(nb);
        c->hb = -hf;
        c->ha = c->hb - c->dist;
    } else if (c->sa.kind != VR_EDGE || c->sb.kind != VR_EDGE || !edge_edge_normal(a, b, c)) {
        point_features(a, b, c);
    }
    return 0;
}

/* ---- the walk's direction and starting vertices ---------------------------- */

static vec3 unit_or_up(vec3 v)
{
    v = vec3_normalize(v);
    return vec3_len2(v) > 0 ? v : vec3_make(0, 0, 1);
}

/* How far apart a (from vertex va) and b (from vb), or a and the point c
 * when b is NULL, are along world direction u: the gap between their
 * support planes, by climbing the vertex graphs. */
typedef struct Gap { const Body *a, *b; vec3 c; int va, vb; } Gap;

static double support_height(const Body *b, vec3 u, int v)
{
    return vec3_dot(u, world_vert(b, vrPolyhedron_Climb(b->p, mat33_tmulv(&b->pose->R, u), v, NULL)));
}

static double gap_along(const Gap *g, vec3 u)
{
    double low_b = g->b ? -support_height(g->b, vec3_neg(u), g->vb) : vec3_dot(u, g->c);
    return low_b - support_height(g->a, u, g->va);
}

/* the normals (times sign) of the faces at feature f of x that separate
 * better than *best does */
static void try_faces(const Gap *g, const Body *x, vrFeature f, double sign, vec3 *best, double *bestgap)
{
    const vrPolyhedron *p = x->p;
    int k, j, lo = f.type == VR_VERTEX ? p->vert_edge_start[f.index] : 0;
    int hi = f.type == VR_VERTEX ? p->vert_edge_start[f.index + 1] : 1;
    for (k = lo; k < hi; k++)
        for (j = 0; j < 2; j++) {
            int e = f.type == VR_VERTEX ? p->vert_edge[k] : f.index;
            vec3 u = vec3_scale(vrPose_rotate(x->pose, p->face_normal[p->edge_f[e][j]]), sign);
            double gu = gap_along(g, u);
            if (gu > *bestgap) *best = u, *bestgap = gu;
        }
}

/* The cross product of edges ea of a and eb of b, when it separates
 * better than *best does.  Crossing edges a hair apart: the direction
 * between the closest points is off by 1e-16 m / gap (7e-9 rad at
 * 1.4e-8 m), which tilts a 26 cm edge 2e-9 m, beyond SUPPORT_TOL, so the
 * edge's lower end alone was taken as b's support and the distance came
 * out 0.21 m for two touching boxes; the cross product is exact. */
static void try_edges(const Gap *g, int ea, int eb, vec3 *best, double *bestgap)
{
    const vrPolyhedron *pa = g->a->p, *pb = g->b->p;
    vec3 da = vrPose_rotate(g->a->pose, vec3_sub(pa->vert[pa->edge_v[ea][1]], pa->vert[pa->edge_v[ea][0]]));
    vec3 db = vrPose_rotate(g->b->pose, vec3_sub(pb->vert[pb->edge_v[eb][1]], pb->vert[pb->edge_v[eb][0]]));
    vec3 u = vec3_cross(da, db);
    double gu, gn;
    if (vec3_len2(u) <= PARALLEL_SIN2 * vec3_len2(da) * vec3_len2(db)) return;
    u = vec3_normalize(u);
    gu = gap_along(g, u);
    gn = gap_along(g, vec3_neg(u));
    if (gn > gu) u = vec3_neg(u), gu = gn;
    if (gu > *bestgap) *best = u, *bestgap = gu;
}

/* Direction of separation at the walk's final features fa, fb (fb unused
 * for a point): a face normal when one is a face (exact however small the
 * gap); else the direction between the closest points.  That direction
 * carries rounding of order 1e-16 m / gap: below GAP_FUZZ the normals of
 * the faces at the features compete with it, and the best separating one
 * wins, so that a plate 1e-12 m above a table, walked to a pair of parallel
 * edges, still finds the table's face. */
#define GAP_FUZZ 1e-6
static vec3 walk_direction(const Gap *g, vrFeature fa, vrFeature fb, vec3 ca, vec3 cb, double dw)
{
    vec3 best;
    double bestgap;
    if (fa.type == VR_FACE) return vrPose_rotate(g->a->pose, g->a->p->face_normal[fa.index]);
    if (g->b && fb.type == VR_FACE) return vec3_neg(vrPose_rotate(g->b->pose, g->b->p->face_normal[fb.index]));
    best = vec3_normalize(vec3_sub(cb, ca));
    if (dw >= GAP_FUZZ * (1 + g->a->p->r_out + (g->b ? g->b->p->r_out : 0))) return best;
    /* closest points that coincide (crossing edges 3e-17 m apart) give no
     * direction at all: the features' own then win whatever their gap */
    bestgap = vec3_len2(best) > 0 ? gap_along(g, best) : -HUGE_VAL;
    if (g->b && fa.type == VR_EDGE && fb.type == VR_EDGE) try_edges(g, fa.index, fb.index, &best, &bestgap);
    if (fa.type == VR_VERTEX || fa.type == VR_EDGE) try_faces(g, g->a, fa, 1, &best, &bestgap);
    if (g->b && (fb.type == VR_VERTEX || fb.type == VR_EDGE)) try_faces(g, g->b, fb, -1, &best, &bestgap);
    if (vec3_len2(best) == 0) best = unit_or_up(vec3_sub(g->b ? g->b->pose->p : g->c, g->a->pose->p));
    return best;
}

/* ---- 2D convex geometry in the contact plane -------------------------------- */

typedef struct P2 { double x, y; } P2;

static P2 p2(double x, double y) { P2 r; r.x = x; r.y = y; return r; }
static P2 p2_sub(P2 a, P2 b) { return p2(a.x - b.x, a.y - b.y); }
static P2 p2_lerp(P2 a, P2 b, double t) { return p2(a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)); }
static double p2_cross(P2 a, P2 b) { return a.x * b.y - a.y * b.x; }
static double p2_dot(P2 a, P2 b) { return a.x * b.x + a.y * b.y; }
static double p2_len(P2 a) { return sqrt(p2_dot(a, a)); }

static int p2_less(P2 a, P2 b) { return a.x < b.x || (a.x == b.x && a.y < b.y); }
/* twice the signed area of o, a, b: > 0 when they turn left */
static double p2_turn(P2 o, P2 a, P2 b) { return p2_cross(p2_sub(a, o), p2_sub(b, o)); }

static void p2_sort(P2 *p, int n)
{
    int i, j;
    for (i = 1; i < n; i++) {
        P2 x = p[i];
        for (j = i; j > 0 && p2_less(x, p[j - 1]); j--) p[j] = p[j - 1];
        p[j] = x;
    }
}

/* a and b lie more than DEDUP_EPS apart (squared: a root is slow) */
static int p2_apart(P2 a, P2 b)
{
    P2 d = p2_sub(a, b);
    return p2_dot(d, d) > DEDUP_EPS * DEDUP_EPS;
}

/* drop points within DEDUP_EPS of their predecessor (cyclically) */
static int p2_dedup(P2 *p, int n)
{
    int i, m = 0;
    for (i = 0; i < n; i++)
        if (m == 0 || p2_apart(p[i], p[m - 1])) p[m++] = p[i];
    while (m > 1 && !p2_apart(p[m - 1], p[0])) m--;
    return m;
}

/* Andrew's monotone chain: counter-clockwise hull without collinear points,
 * in place; a point or a segment when degenerate */
static int hull2d(P2 *p, int n, P2 *tmp)
{
    int i, k = 0, lower;
    p2_sort(p, n);
    n = p2_dedup(p, n);
    if (n < 3) return n;
    for (i = 0; i < n; i++) {
        while (k >= 2 && p2_turn(tmp[k - 2], tmp[k - 1], p[i]) <= 0) k--;
        tmp[k++] = p[i];
    }
    for (i = n - 2, lower = k + 1; i >= 0; i--) {
        while (k >= lower && p2_turn(tmp[k - 2], tmp[k - 1], p[i]) <= 0) k--;
        tmp[k++] = p[i];
    }
    k--; /* the first point closes the loop */
    memcpy(p, tmp, (size_t)k * sizeof *p);
    return p2_dedup(p, k);
}

/* signed distance of x to the left of line a->b (metres) */
static double side(P2 a, P2 b, P2 x) { return p2_cross(p2_sub(b, a), p2_sub(x, a)) / p2_len(p2_sub(b, a)); }

/* The point, segment or polygon `in` clipped to the left of a->b, with the
 * containment tolerance; crossings are cut on the line itself. */
static int clip_halfplane(const P2 *in, int n, P2 a, P2 b, P2 *out)
{
    int i, m = 0;
    if (n == 2) { /* a segment is not a closed loop */
        double s0 = side(a, b, in[0]), s1 = side(a, b, in[1]);
        if (s0 < -REGION_SLACK && s1 < -REGION_SLACK) return 0;
        out[0] = s0 < -REGION_SLACK ? p2_lerp(in[0], in[1], s0 / (s0 - s1)) : in[0];
        out[1] = s1 < -REGION_SLACK ? p2_lerp(in[0], in[1], s0 / (s0 - s1)) : in[1];
        return 2;
    }
    for (i = 0; i < n; i++) { /* Sutherland-Hodgman */
        P2 c = in[i], d = in[(i + 1) % n];
        double sc = side(a, b, c), sd = side(a, b, d);
        int ic = sc >= -REGION_SLACK, id = sd >= -REGION_SLACK;
        if (ic) out[m++] = c;
        if (ic != id && n > 1) {
            double t = sc / (sc - sd);
            out[m++] = p2_lerp(c, d, t < 0 ? 0 : t > 1 ? 1 : t);
        }
    }
    return m;
}

/* two segments (a point is a segment of equal ends), within the tolerance */
static int intersect_segments(const P2 *p, const P2 *q, P2 *out)
{
    P2 d1 = p2_sub(p[1], p[0]), d2 = p2_sub(q[1], q[0]), r = p2_sub(q[0], p[0]);
    double den = p2_cross(d1, d2), l1 = p2_len(d1), l2 = p2_len(d2), u0, u1, lo, hi;
    if (fabs(den) > 1e-12 * l1 * l2) { /* crossing lines */
        double s = p2_cross(r, d2) / den, t = p2_cross(r, d1) / den;
        double ts = REGION_SLACK / l1, tt = REGION_SLACK / l2;
        if (s < -ts || s > 1 + ts || t < -tt || t > 1 + tt) return 0;
        out[0] = p2_lerp(p[0], p[1], s < 0 ? 0 : s > 1 ? 1 : s);
        return 1;
    }
    if (l1 < l2) { /* parallel or points: measure along the longer one, p */
        const P2 *x = p;
        p = q;
        q = x;
        d1 = d2;
        l1 = l2;
    }
    if (l1 <= DEDUP_EPS) { /* two points */
        if (p2_len(p2_sub(q[0], p[0])) > REGION_SLACK) return 0;
        out[0] = p2_lerp(p[0], q[0], 0.5);
        return 1;
    }
    if (fabs(side(p[0], p[1], q[0])) > REGION_SLACK || fabs(side(p[0], p[1], q[1])) > REGION_SLACK) return 0;
    u0 = p2_dot(p2_sub(q[0], p[0]), d1) / (l1 * l1);
    u1 = p2_dot(p2_sub(q[1], p[0]), d1) / (l1 * l1);
    lo = u0 < u1 ? u0 : u1;
    hi = u0 < u1 ? u1 : u0;
    if (lo < 0) lo = 0;
    if (hi > 1) hi = 1;
    if (lo > hi + REGION_SLACK / l1) return 0;
    if (lo > hi) lo = hi = 0.5 * (lo + hi);
    out[0] = p2_lerp(p[0], p[1], lo);
    out[1] = p2_lerp(p[0], p[1], hi);
    return p2_dedup(out, 2);
}

/* Intersection of two convex sets given as hulls (1 point, 2 = a segment,
 * >= 3 = a counter-clockwise polygon): clip the other by the polygon's edges.
 * buf holds np + nq + 2 points. */
static int intersect_hulls(P2 *p, int np, P2 *q, int nq, P2 *out, P2 *buf)
{
    int k, n;
    P2 *cur = out, *next = buf, *swap;
    if (np < 3 && nq < 3) {
        P2 ps[2], qs[2];
        ps[0] = p[0], ps[1] = p[np - 1], qs[0] = q[0], qs[1] = q[nq - 1];
        return intersect_segments(ps, qs, out);
    }
    if (nq < 3) { /* the clipper must be the polygon */
        swap = p, p = q, q = swap;
        k = np, np = nq, nq = k;
    }
    memcpy(cur, p, (size_t)np * sizeof *p);
    n = np;
    for (k = 0; k < nq && n > 0; k++) {
        n = clip_halfplane(cur, n, q[k], q[(k + 1) % nq], next);
        if (n > 2) n = p2_dedup(next, n);
        swap = cur, cur = next, next = swap;
    }
    if (cur != out) memcpy(out, cur, (size_t)n * sizeof *out);
    return n;
}

/* at most VR_REGION_MAX points: the extremes of the polygon along as many
 * evenly spread directions, in polygon order */
static int reduce(P2 *p, int n)
{
    int idx[VR_REGION_MAX], i, k, m = 0;
    if (n <= VR_REGION_MAX) return n;
    for (k = 0; k < VR_REGION_MAX; k++) {
        P2 d = p2(cos(2 * VR_PI * k / VR_REGION_MAX), sin(2 * VR_PI * k / VR_REGION_MAX));
        int best = 0;
        for (i = 1; i < n; i++)
            if (p2_dot(d, p[i]) > p2_dot(d, p[best])) best = i;
        for (i = k; i > 0 && idx[i - 1] > best; i--) idx[i] = idx[i - 1];
        idx[i] = best;
    }
    for (k = 0; k < VR_REGION_MAX; k++) /* idx ascending: compaction in place is safe */
        if (k == 0 || idx[k] != idx[k - 1]) p[m++] = p[idx[k]];
    return m;
}

/* ---- contact region (SPEC 2) ------------------------------------------------ */

/* vertices of b at world height >= floor along n, searched from seed */
static int slab(const Body *b, vec3 n, double floor, int seed, IntSet *out)
{
    return collect(b->p, mat33_tmulv(&b->pose->R, n), seed, floor - vec3_dot(n, b->pose->p), out);
}

static void project(const Body *b, const IntSet *s, vec3 t1, vec3 t2, P2 *out)
{
    int i;
    for (i = 0; i < s->n; i++) {
        vec3 x = world_vert(b, s->v[i]);
        out[i] = p2(vec3_dot(t1, x), vec3_dot(t2, x));
    }
}

/* Step 5: the vertices of each body within d of the other's support plane,
 * projected on the plane normal to n, hulled, intersected, and lifted to the
 * plane midway between the support planes. */
static int region_points(const Body *a, const Body *b, const Canon *c, const IntSet *va, const IntSet *vb,
                         vrContact *out)
{
    P2 stack[256], *buf = stack, *pa, *pb, *tmp, *res, *clip;
    int na, nb, m, i, n = va->n + vb->n;
    vec3 t1 = vec3_orthogonal(c->n), t2 = vec3_cross(c->n, t1);
    double mid = 0.5 * (c->ha + c->hb);
    /* a and b's points, the hull's chain (2n), the intersection and its scratch */
    if (5 * n + 6 > 256 && !(buf = malloc((5 * (size_t)n + 6) * sizeof *buf))) return -1;
    pa = buf, pb = pa + va->n, tmp = pb + vb->n, res = tmp + 2 * n + 2, clip = res + n + 2;
    project(a, va, t1, t2, pa);
    project(b, vb, t1, t2, pb);
    na = hull2d(pa, va->n, tmp);
    nb = hull2d(pb, vb->n, tmp);
    m = reduce(res, intersect_hulls(pa, na, pb, nb, res, clip));
    for (i = 0; i < m; i++)
        out->point[i] = vec3_madd(vec3_add(vec3_scale(t1, res[i].x), vec3_scale(t2, res[i].y)), mid, c->n);
    out->npoints = m;
    if (m == 0) { /* tolerance corner cases */
        out->npoints = 1;
        out->point[0] = vec3_lerp(c->qa, c->qb, 0.5);
    }
    if (buf != stack) free(buf);
    return 0;
}

static int region_poly(const Body *a, const Body *b, const Canon *c, double d, vrContact *out)
{
    IntSet va, vb;
    int rc;
    set_init(&va);
    set_init(&vb);
    rc = slab(b, vec3_neg(c->n), -(c->ha + d + REGION_SLACK), c->sb.v.v[0], &vb)
      || slab(a, c->n, c->hb - d - REGION_SLACK, c->sa.v.v[0], &va)
      || region_points(a, b, c, &va, &vb, out);
    set_free(&va);
    set_free(&vb);
    return rc ? -1 : 0;
}

/* ---- the entry points ------------------------------------------------------- */

static void set_result(vrContact *out, double dist, vec3 n, vec3 pa, vec3 pb)
{
    out->dist = dist;
    out->n = n;
    out->pa = pa;
    out->pb = pb;
}

/* Gaps the walk measures below this are rounding: whether it sees the
 * shapes a hair apart or a hair inside each other depends on where it
 * started (a worker's cache differs from the serial owner's), so neither
 * answer is used as it is (m). */
#define TOUCH_TOL 1e-12

/* An overlap no deeper than this is a touch (m).  libccd's MPR stops at
 * that tolerance (penetration.c), and for shapes that only touch its
 * direction is that of a portal vertex, not a normal: a cube set exactly on
 * a floor got (0.35, 0.94, 0), and a board sliding on the floor with a
 * corner down took contact impulses sideways from the floor, momentum from
 * nowhere.  Nor does a walk that stopped on finding the overlap end on the
 * touching features.  The face normal along which the shapes lie farthest
 * apart (a separating-axis test over both shapes' faces) is the touching
 * face's for a vertex, an edge or a face on a face, and the canonical
 * features along it give normal, distance and region, as they do for
 * shapes a hair apart.  Crossed edges touching (no face separates) stay
 * libccd's. */
#define SHALLOW_TOL 1e-9

/* the shapes overlap deeper than SHALLOW_TOL, by libccd */
static int deep_overlap(const vrShape *a, const vrPose *pa, const vrShape *b, const vrPose *pb)
{
    double depth;
    vec3 dir, pos;
    return vrPenetration(a, pa, b, pb, &depth, &dir, &pos) == 0 && depth > SHALLOW_TOL;
}

/* the face normal (a's, or minus b's) along which a and b are farthest
 * apart, and that gap; a's first face on a tie */
static vec3 touching_axis(const Gap *g, double *gap)
{
    vec3 best = vec3_zero();
    int side, f;
    *gap = -HUGE_VAL;
    for (side = 0; side < 2; side++) {
        const Body *x = side ? g->b : g->a;
        for (f = 0; f < x->p->nf; f++) {
            vec3 u = vrPose_rotate(x->pose, x->p->face_normal[f]);
            double h;
            if (side) u = vec3_neg(u);
            if ((h = gap_along(g, u)) > *gap) *gap = h, best = u;
        }
    }
    return best;
}

/* Shapes that touch by the walk: the canonical features along the
 * touching axis, when the shapes are no more than SHALLOW_TOL apart or
 * into each other along it, by it and by libccd alike; else -1 */
static int touching_features(const vrShape *a, const vrPose *pa, const vrShape *b, const vrPose *pb, Gap *g,
                             vrFeature fa, vrFeature fb, Canon *c)
{
    double gap;
    vec3 axis = touching_axis(g, &gap);
    if (!(fabs(gap) <= SHALLOW_TOL) || deep_overlap(a, pa, b, pb)) return -1;
    if (canonical(g->a, g->b, axis, fa, fb, c) != 0 || !(fabs(c->dist) <= SHALLOW_TOL)) return -1;
    return 0;
}

/* Overlap: libccd's depth, direction and position (step 7), or the face
 * normal of either shape along which they overlap least, when that is
 * shallower (a separating-axis test; translating by its overlap along it
 * separates them).  MPR's direction is the portal's it refines from the
 * centre line: for a small box in a tall wall's corner with the floor it
 * pointed 82 degrees off the wall's face, and the push-out along it drove
 * the box 13 cm down into the floor (physics fuzzer seed 3249).  When
 * libccd sees no overlap (grazing contact) the pair touches: distance 0. */
static int penetration_contact(const vrShape *a, const vrPose *pa, const vrShape *b, const vrPose *pb, double d,
                               const Gap *g, vec3 ca, vec3 cb, vrContact *out)
{
    double depth, gap;
    vec3 dir, pos, axis;
    if (vrPenetration(a, pa, b, pb, &depth, &dir, &pos) == 0) {
        axis = touching_axis(g, &gap);
        if (gap < 0 && -gap < depth) set_result(out, gap, axis, pos, pos);
        else set_result(out, -depth, unit_or_up(dir), pos, pos);
    } else {
        pos = vec3_lerp(ca, cb, 0.5);
        set_result(out, 0, unit_or_up(vec3_sub(pb->p, pa->p)), pos, pos);
    }
    if (d >= 0) {
        out->npoints = 1;
        out->point[0] = pos;
    }
    return 0;
}

/* steps 2-5 after the walk (dw, ca, cb, pen: its result, the cache at
 * its end): the canonical features, distance and normal, and the region.
 * Shapes touching within TOUCH_TOL: the walk is made again from a fixed
 * start, so that what follows is a pure function of the poses.  Shapes
 * that overlap go to libccd, unless they only touch (SHALLOW_TOL). */
static int poly_finish(const vrShape *a, const vrPose *pa, const vrShape *b, const vrPose *pb, double d,
                       vrWalkCache *cache, double dw, vec3 ca, vec3 cb, int pen, vrContact *out)
{
    Body ba, bb;
    Canon c;
    Gap g;
    vrWalkCache fresh;
    int rc;
    if (pen || !(dw > TOUCH_TOL)) {
        memset(&fresh, 0, sizeof fresh);
        cache = &fresh;
        dw = vrClosest_Walk(a->poly, pa, b->poly, pb, cache, &ca, &cb, NULL, &pen);
    }
    ba.p = a->poly, ba.pose = pa, bb.p = b->poly, bb.pose = pb;
    canon_init(&c);
    g.a = &ba, g.b = &bb, g.va = vrFeature_Vertex(ba.p, cache->a), g.vb = vrFeature_Vertex(bb.p, cache->b);
    if (pen || !(dw > 0)) {
        rc = touching_features(a, pa, b, pb, &g, cache->a, cache->b, &c);
    } else {
        rc = canonical(&ba, &bb, walk_direction(&g, cache->a, cache->b, ca, cb, dw), cache->a, cache->b, &c);
        if (rc == 0 && !(c.dist > 0)) { /* the canonical features touch */
            canon_free(&c);
            canon_init(&c);
            rc = touching_features(a, pa, b, pb, &g, cache->a, cache->b, &c);
        }
    }
    if (rc != 0) {   /* an overlap (or out of memory: libccd then too) */
        canon_free(&c);
        return penetration_contact(a, pa, b, pb, d, &g, ca, cb, out);
    }
    set_result(out, c.dist, c.n, c.qa, c.qb);
    if (d >= 0 && c.dist <= d) rc = region_poly(&ba, &bb, &c, d, out);
    canon_free(&c);
    return rc;
}

static int poly_contact(const vrShape *a, const vrPose *pa, const vrShape *b, const vrPose *pb, double d,
                        vrWalkCache *cache, vrContact *out)
{
    vec3 ca, cb;
    int pen;
    double dw;
    if (!a->poly || !b->poly) return -1;
    dw = vrClosest_Walk(a->poly, pa, b->poly, pb, cache, &ca, &cb, &out->walk_steps, &pen);
    return poly_finish(a, pa, b, pb, d, cache, dw, ca, cb, pen, out);
}

/* ---- spheres (step 6) ----------------------------------------------------- */

/* What a sphere's centre c sees of the other shape: its closest point q, the
 * unit direction from the shape toward c, and c's signed distance (negative
 * inside). */
typedef struct Near { vec3 q, dir; double dist; } Near;

static Near near_sphere(vec3 centre, double r, vec3 c)
{
    Near nr;
    nr.dir = unit_or_up(vec3_sub(c, centre));
    nr.dist = vec3_dist(c, centre) - r;
    nr.q = vec3_madd(centre, r, nr.dir);
    return nr;
}

/* closed form: clamp the centre into the box (its frame); inside, the
 * nearest face (lowest axis on ties) */
static Near near_box(const vrShape *box, const vrPose *pose, vec3 c)
{
    double x[3], h[3] = {box->half.x, box->half.y, box->half.z}, q[3];
    vec3 xl = vrPose_invapply(pose, c);
    int i, inside = 1, axis = 0;
    Near nr;
    x[0] = xl.x, x[1] = xl.y, x[2] = xl.z;
    for (i = 0; i < 3; i++) {
        q[i] = x[i] < -h[i] ? -h[i] : x[i] > h[i] ? h[i] : x[i];
        if (q[i] != x[i]) inside = 0;
        if (h[i] - fabs(x[i]) < h[axis] - fabs(x[axis])) axis = i;
    }
    if (inside) {
        double s = x[axis] < 0 ? -1 : 1;
        nr.dist = -(h[axis] - fabs(x[axis]));
        q[axis] = s * h[axis];
        nr.dir = vrPose_rotate(pose, vec3_make(axis == 0 ? s : 0, axis == 1 ? s : 0, axis == 2 ? s : 0));
    } else {
        vec3 diff = vec3_sub(xl, vec3_make(q[0], q[1], q[2]));
        nr.dist = vec3_len(diff);
        nr.dir = vrPose_rotate(pose, vec3_scale(diff, 1.0 / nr.dist));
    }
    nr.q = vrPose_apply(pose, vec3_make(q[0], q[1], q[2]));
    return nr;
}

/* the walk to the centre, then the canonical support feature toward it */
static int near_poly(const Body *b, vec3 c, vrWalkCache *cache, int *steps, Near *nr)
{
    Support s;
    Gap g;
    vec3 q, dir;
    double dw = vrClosest_WalkPoint(b->p, b->pose, c, cache, &q, steps);
    vrFeature f = cache->a;
    if (f.type == VR_FACE && dw <= 0) { /* inside: the walk scanned every face plane */
        double h;
        nr->dir = face_plane(b, f.index, &h);
        nr->dist = vec3_dot(nr->dir, c) - h;
        nr->q = vec3_madd(c, -nr->dist, nr->dir);
        return 0;
    }
    if (!(dw > 0)) { /* the centre on an edge or vertex */
        nr->dir = unit_or_up(vec3_sub(c, b->pose->p));
        nr->dist = 0;
        nr->q = c;
        return 0;
    }
    g.a = b, g.b = NULL, g.c = c, g.va = vrFeature_Vertex(b->p, f), g.vb = 0;
    dir = walk_direction(&g, f, f, q, c, dw);
    set_init(&s.v);
    if (support_feature(b, dir, f, &s)) {
        set_free(&s.v);
        return -1;
    }
    if (s.kind == VR_FACE) {
        double h;
        nr->dir = face_plane(b, s.index, &h);
        nr->dist = vec3_dot(nr->dir, c) - h;
        nr->q = vec3_madd(c, -nr->dist, nr->dir);
    } else {
        vec3 p0, p1;
        feature_segment(b, &s, &p0, &p1);
        nr->q = vec3_lerp(p0, p1, vrSegment_PointParam(p0, p1, c));
        nr->dist = vec3_dist(c, nr->q);
        nr->dir = nr->dist > 0 ? vec3_scale(vec3_sub(c, nr->q), 1 / nr->dist) : dir;
    }
    set_free(&s.v);
    return 0;
}

/* A true sphere against anything: measure from the sphere's centre (b's
 * when both are spheres), then orient a -> b. */
static int sphere_contact(const vrShape *a, const vrPose *pa, const vrShape *b, const vrPose *pb, double d,
                          vrWalkCache *cache, vrContact *out)
{
    int sb = b->kind == VR_SHAPE_SPHERE, rc = 0;
    const vrShape *s = sb ? b : a, *o = sb ? a : b;
    const vrPose *ps = sb ? pb : pa, *po = sb ? pa : pb;
    vec3 sp, pos, at;
    Near nr;
    double dist;
    out->walk_steps = 0;
    if (o->kind == VR_SHAPE_SPHERE) {
        nr = near_sphere(po->p, o->radius, ps->p);
    } else if (o->kind == VR_SHAPE_BOX) {
        nr = near_box(o, po, ps->p);
    } else {
        Body bo;
        bo.p = o->poly, bo.pose = po;
        if (!bo.p || near_poly(&bo, ps->p, cache, &out->walk_steps, &nr)) return -1;
    }
    dist = nr.dist - s->radius;
    sp = vec3_madd(ps->p, -s->radius, nr.dir); /* the sphere's closest point */
    pos = vec3_lerp(nr.q, sp, 0.5);
    if (dist <= 0)
        set_result(out, dist, sb ? nr.dir : vec3_neg(nr.dir), pos, pos);
    else
        set_result(out, dist, sb ? nr.dir : vec3_neg(nr.dir), sb ? nr.q : sp, sb ? sp : nr.q);
    at = dist <= 0 || o->kind == VR_SHAPE_SPHERE ? pos : sp;
    if (d >= 0 && dist <= d) {
        out->npoints = 1;
        out->point[0] = at;
    }
    return rc;
}

static int contact(const vrShape *a, const vrPose *pa, const vrShape *b, const vrPose *pb, double d,
                   vrWalkCache *cache, vrContact *out)
{
    vrWalkCache local;
    if (!cache) {
        memset(&local, 0, sizeof local);
        cache = &local;
    }
    out->npoints = 0;
    out->walk_steps = 0;
    if (a->kind == VR_SHAPE_SPHERE || b->kind == VR_SHAPE_SPHERE) return sphere_contact(a, pa, b, pb, d, cache, out);
    return poly_contact(a, pa, b, pb, d, cache, out);
}

/* ---- support containment (SPEC 3.1) ------------------------------------- */

static int cmp_p2(const void *a, const void *b)
{
    const P2 *p = a, *q = b;
    return p2_less(*p, *q) ? -1 : p2_less(*q, *p);
}

/* distance from the origin to segment ab */
static double seg_dist(P2 a, P2 b)
{
    double ex = b.x - a.x, ey = b.y - a.y, l2 = ex * ex + ey * ey;
    double s = l2 > 0 ? -(a.x * ex + a.y * ey) / l2 : 0;
    s = s < 0 ? 0 : s > 1 ? 1 : s;
    return hypot(a.x + s * ex, a.y + s * ey);
}

vec3 vrShape_Support(const vrShape *s, const vrPose *p, vec3 dir)
{
    vec3 d;
    int i, best = 0;
    double m;
    if (s->kind == VR_SHAPE_SPHERE) return vec3_madd(p->p, s->radius, vec3_normalize(dir));
    d = mat33_tmulv(&p->R, dir);     /* in the body frame: one rotation, not one per vertex */
    m = vec3_dot(d, s->poly->vert[0]);
    for (i = 1; i < s->poly->nv; i++) {
        double h = vec3_dot(d, s->poly->vert[i]);
        if (h > m) {
            m = h;
            best = i;
        }
    }
    return vrPose_apply(p, s->poly->vert[best]);
}

/* Does p[0..n) go once round a convex polygon counter-clockwise, every
 * corner turning left by more than rounding (sine above TURN_MIN), all
 * seen from p[0] in order within half a turn (left turns alone also let a
 * star go round twice)?  A region made by region_points does, in one
 * sense or the other; its hull is then itself, as the monotone chain
 * would find it, and the edge tests give the same bits. */
#define TURN_MIN 1e-9

static int strictly_convex(const P2 *p, int n)
{
    int i;
    for (i = 0; i < n; i++) {
        P2 a = p[i], b = p[(i + 1) % n], c = p[(i + 2) % n], ab = p2_sub(b, a), bc = p2_sub(c, b);
        double turn = p2_turn(a, b, c);
        if (!(turn > 0 && turn * turn > TURN_MIN * TURN_MIN * p2_dot(ab, ab) * p2_dot(bc, bc))) return 0;
    }
    for (i = 2; i < n; i++)      /* left of p[0]->p[1], and turning on: within half a turn */
        if (!(p2_turn(p[0], p[1], p[i]) > 0 && p2_turn(p[0], p[i - 1], p[i]) > 0)) return 0;
    return 1;
}

/* how far the origin lies inside convex counter-clockwise polygon h */
static double inside_by(const P2 *h, int k)
{
    double margin = INFINITY;
    int i;
    for (i = 0; i < k; i++) {
        P2 a = h[i], b = h[(i + 1) % k];
        double len = p2_len(p2_sub(b, a)), in;
        if (!(len > 0)) continue;
        in = p2_turn(a, b, p2(0, 0)) / len;
        if (in < margin) margin = in;
    }
    return margin;
}

/* a contact region as it is (convex, in order), else Andrew's monotone
 * chain first; then edge tests */
double vrRegion_Margin(const vec3 *pts, int n, vec3 nrm, vec3 q)
{
    vec3 t1 = vec3_orthogonal(nrm), t2 = vec3_cross(nrm, t1);
    P2 small[VR_REGION_MAX], hsmall[2 * VR_REGION_MAX], *p = small, *h = hsmall;
    int i, k = 0, lower;
    double margin = INFINITY;
    if (n > VR_REGION_MAX) {       /* several supports' regions together */
        p = malloc((size_t)n * sizeof *p);
        h = malloc((size_t)(2 * n) * sizeof *h);
        if (!p || !h) {
            free(p == small ? NULL : p);
            free(h == hsmall ? NULL : h);
            return -INFINITY;
        }
    }
    for (i = 0; i < n; i++) {
        vec3 d = vec3_sub(pts[i], q);
        p[i].x = vec3_dot(d, t1);
        p[i].y = vec3_dot(d, t2);
    }
    if (n >= 3 && n <= VR_REGION_MAX) {
        if (strictly_convex(p, n)) return inside_by(p, n);
        for (i = 0; i < n; i++) h[i] = p[n - 1 - i];     /* the other sense */
        if (strictly_convex(h, n)) return inside_by(h, n);
    }
    qsort(p, (size_t)n, sizeof *p, cmp_p2);
    for (i = 0; i < n; i++) {
        while (k >= 2 && p2_turn(h[k - 2], h[k - 1], p[i]) <= 0) k--;
        h[k++] = p[i];
    }
    for (i = n - 2, lower = k + 1; i >= 0; i--) {
        while (k >= lower && p2_turn(h[k - 2], h[k - 1], p[i]) <= 0) k--;
        h[k++] = p[i];
    }
    if (k > 1) k--;                                /* the last point repeats the first */
    if (k == 1) margin = -hypot(h[0].x, h[0].y);
    else if (k == 2) margin = -seg_dist(h[0], h[1]);
    if (k > 2) margin = inside_by(h, k);
    if (p != small) free(p);
    if (h != hsmall) free(h);
    return margin;
}

int vrRegion_Contains(const vec3 *pts, int n, vec3 nrm, vec3 q, double tol)
{
    return vrRegion_Margin(pts, n, nrm, q) >= -tol;
}

int vrContact_Quick(const vrShape *a, const vrPose *pa, const vrShape *b, const vrPose *pb,
                    vrWalkCache *cache, double *dist, vec3 *n)
{
    vec3 ca, cb;
    int pen;
    double dw;
    if (a->kind == VR_SHAPE_SPHERE || b->kind == VR_SHAPE_SPHERE || !a->poly || !b->poly || !cache) return -1;
    dw = vrClosest_Walk(a->poly, pa, b->poly, pb, cache, &ca, &cb, NULL, &pen);
    if (pen || !(dw > 0)) return -1;
    *dist = dw;
    *n = vec3_scale(vec3_sub(cb, ca), 1.0 / dw);
    return 0;
}

/* One walk: its own distance when that is clear of d, else the canonical
 * distance finished from the same walk (a second walk from where the first
 * ended would only confirm it). */
int vrContact_Within(const vrShape *a, const vrPose *pa, const vrShape *b, const vrPose *pb,
                     vrWalkCache *cache, double d, vrContact *seen)
{
    vrContact c;
    vec3 ca, cb;
    int pen;
    double dw;
    if (!seen) seen = &c;
    if (a->kind == VR_SHAPE_SPHERE || b->kind == VR_SHAPE_SPHERE || !a->poly || !b->poly || !cache) {
        contact(a, pa, b, pb, -1, cache, seen);
        return seen->dist <= d;
    }
    dw = vrClosest_Walk(a->poly, pa, b->poly, pb, cache, &ca, &cb, NULL, &pen);
    seen->dist = pen ? fmin(dw, 0.0) : dw;
    seen->pa = ca;
    seen->pb = cb;
    if (!pen && dw > 0 && fabs(dw - d) > VR_QUICK_TOL) return dw < d;
    c.dist = dw;
    c.npoints = 0;
    poly_finish(a, pa, b, pb, -1, cache, dw, ca, cb, pen, &c);
    return c.dist <= d;
}

int vrContact_Distance(const vrShape *a, const vrPose *pa, const vrShape *b, const vrPose *pb,
                       vrWalkCache *cache, vrContact *out)
{
    return contact(a, pa, b, pb, -1, cache, out);
}

int vrContact_Region(const vrShape *a, const vrPose *pa, const vrShape *b, const vrPose *pb,
                     double d, vrWalkCache *cache, vrContact *out)
{
    return contact(a, pa, b, pb, d < 0 ? 0 : d, cache, out);
}
