/* canonical.c — the canonical support features and the canonical distance
 * and normal of a posed pair of polyhedra (SPEC 2 "Contact region", SPEC 3.2
 * determinism rules, thesis 3.2.1).
 *
 * The walk (closest.c) only finds A closest feature pair.  When faces are
 * parallel many pairs are equally closest (a box flat on a table: vertex-
 * face, edge-face, face-face), and which one the walk ends on depends on
 * where its cache started.  So nothing is taken from the walk's result but
 * a direction (separation.c, vrGap_WalkDirection): from it we build each body's
 * near-support set (vertices within SUPPORT_TOL of the supporting plane),
 * classify it as a vertex, an edge or a face (vrSupportFeature_Find), and
 * compute distance, normal and closest points from those features and the
 * poses alone, by fixed formulas (vrCanon_Compute):
 *   a's face -> its normal;  else b's face -> minus its normal (the
 *     other feature measured where it lies over the face, overhang.c);
 *   edge x edge (not parallel) -> the cross product;
 *   otherwise the closest points of the two features, a vertex feature
 *   from which an edge goes nearer the other's closest point taken as
 *   that edge (the support set missed its far end by a rounding), and of
 *   two edges taken as parallel, an end nearer than their overlap's
 *   middle as a vertex.
 * The contact region (region.c) is built from the same features.  (Left to
 * chance: a set member within rounding of the 1e-9 m threshold.)
 *   support_set                      the near-support set
 *   edge_between, face_of_set,       the feature a set is
 *   set_to_face, face_is_support
 *   face_against, edge_edge_normal,  the normal and distance by the kinds of
 *   point_features                   the two features
 *   nearer_edge, complete,           a vertex feature completed to its edge,
 *   nearer_end, reduce,              parallel edges reduced to an end
 *   edges_and_vertices
 *
 * No static state; scratch memory lives on the stack unless a set outgrows
 * its inline buffer.
 */
#include <stdlib.h>
#include <string.h>

#include "canonical.h"
#include "overhang.h"
#include "polyhedron.h"
#include "segment.h"

#define SUPPORT_TOL 1e-9   /* tau: near-support set tolerance (m) */
#define COMPLETE_TOL 1e-12 /* m: an edge from a vertex feature going no nearer than this
                            * is left: the distance is then at most this long (far
                            * above the rounding of coordinates of a 60 m room) */


/* The near-support set of b in world direction dir: the vertices within
 * SUPPORT_TOL of the highest, ascending.  The filter after the search makes
 * the set independent of which top vertex the climb reached. */
static int support_set(const vrPosed *b, vec3 dir, int start, vrIntSet *out)
{
    vec3 d = mat33_tmulv(&b->pose->R, dir);
    double top, gap;
    int v = vrPolyhedron_Climb(b->p, d, start, &gap), i, n = 0;
    if (gap > SUPPORT_TOL) return vrIntSet_Add(out, v); /* a lone top vertex: the common case */
    if (vrIntSet_Collect(b->p, d, v, vec3_dot(d, b->p->vert[v]) - SUPPORT_TOL, out)) return -1;
    top = vec3_dot(d, b->p->vert[out->v[0]]);
    for (i = 1; i < out->n; i++)
        if (vec3_dot(d, b->p->vert[out->v[i]]) > top) top = vec3_dot(d, b->p->vert[out->v[i]]);
    for (i = 0; i < out->n; i++)
        if (vec3_dot(d, b->p->vert[out->v[i]]) >= top - SUPPORT_TOL) out->v[n++] = out->v[i];
    out->n = n;
    vrIntSet_Sort(out);
    return 0;
}

/* ---- support features ----------------------------------------------------- */

static int edge_between(const vrPolyhedron *p, int v, int w)
{
    int k;
    for (k = p->vert_edge_start[v]; k < p->vert_edge_start[v + 1]; k++)
        if (vrPolyhedron_OtherEnd(p, p->vert_edge[k], v) == w) return p->vert_edge[k];
    return -1;
}

static int face_within(const vrPolyhedron *p, int f, const vrIntSet *s)
{
    int k;
    for (k = p->face_start[f]; k < p->face_start[f + 1]; k++)
        if (!vrIntSet_Has(s, p->face_vert[k])) return 0;
    return 1;
}

/* the face around s's vertices whose vertices all lie in s: an exact match
 * if there is one, else the one facing d best (lowest index on ties); -1 if none */
static int face_of_set(const vrPolyhedron *p, vec3 d, const vrIntSet *s)
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

static int set_to_face(const vrPolyhedron *p, int f, vrIntSet *s)
{
    int k;
    s->n = 0;
    for (k = p->face_start[f]; k < p->face_start[f + 1]; k++)
        if (vrIntSet_Add(s, p->face_vert[k])) return -1;
    vrIntSet_Sort(s);
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
 * Sets that are none of these fall back to a face inside the set, or to
 * the segment between the set's two farthest vertices: an edge of no
 * index (vrSupportFeature_Segment).  Such a set is mostly a line of
 * vertices along a flat side (a boxy superquadric's meridian: three in a
 * row within 1e-9 m of the top); taken as its highest vertex, the
 * distance was measured from one end of the line, 8 mm where the bodies
 * were 1 mm apart, and the pair left the envelope for a grid step (the
 * physics fuzzer's seed 2043, heap on and off then parting).  When the
 * walk ended on a face that is the support (a box on a table), it is
 * taken at once. */
int vrSupportFeature_Find(const vrPosed *b, vec3 dir, vrFeature from, vrSupportFeature *s)
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
    s->kind = s->v.n == 1 ? VR_VERTEX : VR_EDGE;
    s->index = s->v.n == 1 ? s->v.v[0] : -1;
    return 0;
}

/* the two of set s's vertices farthest apart (the first such pair in
 * ascending order), body frame */
static void farthest_pair(const vrPolyhedron *p, const vrIntSet *s, int *v0, int *v1)
{
    double most = -1;
    int i, j;
    *v0 = *v1 = s->v[0];
    for (i = 0; i < s->n; i++)
        for (j = i + 1; j < s->n; j++) {
            double d2 = vec3_len2(vec3_sub(p->vert[s->v[i]], p->vert[s->v[j]]));
            if (d2 > most) most = d2, *v0 = s->v[i], *v1 = s->v[j];
        }
}

/* ---- canonical distance and normal ---------------------------------------- */

void vrCanon_Init(vrCanon *c)
{
    vrIntSet_Init(&c->sa.v);
    vrIntSet_Init(&c->sb.v);
}

void vrCanon_Free(vrCanon *c)
{
    vrIntSet_Free(&c->sa.v);
    vrIntSet_Free(&c->sb.v);
}

static double min_height(const vrPosed *b, const vrIntSet *s, vec3 n)
{
    double m = HUGE_VAL;
    int i;
    for (i = 0; i < s->n; i++) {
        double h = vec3_dot(n, vrPosed_Vertex(b, s->v[i]));
        if (h < m) m = h;
    }
    return m;
}

static vec3 centroid(const vrPosed *b, const vrIntSet *s)
{
    vec3 c = vec3_zero();
    int i;
    for (i = 0; i < s->n; i++) c = vec3_add(c, vrPosed_Vertex(b, s->v[i]));
    return vec3_scale(c, 1.0 / s->n);
}

/* face f of fb (world plane n.x = h) against the support feature s of
 * `other`: the distance from its lowest vertex, the closest points from
 * its centroid; from the part over the face where it reaches past the face
 * (overhang.c) */
static int face_against(const vrPosed *fb, int f, vec3 n, double h, const vrPosed *other, const vrSupportFeature *s,
                        vec3 *q_face, vec3 *q_other, double *dist)
{
    double low;
    int over = vrOverhang_Lowest(fb, f, n, other, s, &low, q_other);
    if (over < 0) return -1;
    if (!over) low = min_height(other, &s->v, n), *q_other = centroid(other, &s->v);
    *dist = low - h;
    *q_face = vec3_madd(*q_other, -(vec3_dot(n, *q_other) - h), n);
    return 0;
}

/* the end vertices of a vertex or edge support feature (a vertex twice) */
static void segment_ends(const vrPosed *b, const vrSupportFeature *s, int *t, int *h)
{
    if (s->kind == VR_EDGE && s->index >= 0) *t = b->p->edge_v[s->index][0], *h = b->p->edge_v[s->index][1];
    else if (s->kind == VR_EDGE) farthest_pair(b->p, &s->v, t, h);   /* a line of vertices */
    else *t = *h = s->index;                                          /* a vertex */
}

/* end points of a vertex or edge support feature, world (a vertex twice) */
void vrSupportFeature_Segment(const vrPosed *b, const vrSupportFeature *s, vec3 *p0, vec3 *p1)
{
    int t, h;
    segment_ends(b, s, &t, &h);
    *p0 = vrPosed_Vertex(b, t);
    *p1 = vrPosed_Vertex(b, h);
}

/* edge x edge: n = normalised cross product of the stored edges, pointing
 * from a's centre side to b's; 0 when the edges are parallel */
static int edge_edge_normal(const vrPosed *a, const vrPosed *b, vrCanon *c)
{
    vec3 a0, a1, b0, b1, ea, eb, n;
    double s, t;
    vrSupportFeature_Segment(a, &c->sa, &a0, &a1);
    vrSupportFeature_Segment(b, &c->sb, &b0, &b1);
    ea = vec3_sub(a1, a0);
    eb = vec3_sub(b1, b0);
    n = vec3_cross(ea, eb);
    if (vec3_len2(n) <= VR_PARALLEL_SIN2 * vec3_len2(ea) * vec3_len2(eb)) return 0;
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
static void point_features(const vrPosed *a, const vrPosed *b, vrCanon *c)
{
    vec3 a0, a1, b0, b1;
    double s, t;
    vrSupportFeature_Segment(a, &c->sa, &a0, &a1);
    vrSupportFeature_Segment(b, &c->sb, &b0, &b1);
    vrSegment_ClosestParams(a0, a1, b0, b1, &s, &t);
    c->qa = vec3_lerp(a0, a1, s);
    c->qb = vec3_lerp(b0, b1, t);
    c->dist = vec3_dist(c->qa, c->qb);
    c->n = vec3_normalize(vec3_sub(c->qb, c->qa));
    c->ha = -min_height(a, &c->sa.v, vec3_neg(c->n));
    c->hb = min_height(b, &c->sb.v, c->n);
}

/* An edge leaving vertex v of b that goes more than COMPLETE_TOL nearer q
 * (the farthest such, the first on ties), or -1.  The closest points of
 * a vertex and the other feature are the bodies' closest points only if
 * none does. */
static int nearer_edge(const vrPosed *b, int v, vec3 q)
{
    const vrPolyhedron *p = b->p;
    vec3 x = vrPosed_Vertex(b, v), to = vec3_sub(q, x);
    double most = COMPLETE_TOL;
    int k, best = -1;
    for (k = p->vert_edge_start[v]; k < p->vert_edge_start[v + 1]; k++) {
        int e = p->vert_edge[k];
        vec3 u = vec3_sub(vrPosed_Vertex(b, vrPolyhedron_OtherEnd(p, e, v)), x);
        double along = vec3_dot(to, u) / vec3_len(u);
        if (along > most) most = along, best = e;
    }
    return best;
}

/* A vertex feature of b from which an edge goes nearer q (the other
 * feature's closest point) becomes that edge; 1 if it did (-1: no memory).
 * Two upright edges side by side, near parallel (the physics fuzzer's seed
 * 10473): the walk's direction was square to one edge and 8e-9 rad off the
 * other, whose far end then dropped past SUPPORT_TOL; its support was its
 * top vertex alone, above the other box's top, and boxes 1.86 cm apart
 * measured 8.97 cm, so the heap put their pair off for 144 s.  Decided from
 * the features and the poses alone, never the direction: a run whose
 * direction gave the edge at once agrees, and two runs that chose the
 * same features complete them alike (a rule on the direction, within some
 * angle, parted heap on and off on seed 1661). */
static int complete(const vrPosed *b, vrSupportFeature *s, vec3 q)
{
    int e;
    if (s->kind != VR_VERTEX || (e = nearer_edge(b, s->index, q)) < 0) return 0;
    s->kind = VR_EDGE;
    s->index = e;
    s->v.n = 0;
    if (vrIntSet_Add(&s->v, b->p->edge_v[e][0]) || vrIntSet_Add(&s->v, b->p->edge_v[e][1])) return -1;
    vrIntSet_Sort(&s->v);
    return 1;
}

/* the distance from x to feature s's segment */
static double to_segment(const vrPosed *b, const vrSupportFeature *s, vec3 x)
{
    vec3 p0, p1;
    vrSupportFeature_Segment(b, s, &p0, &p1);
    return vec3_dist(x, vec3_lerp(p0, p1, vrSegment_PointParam(p0, p1, x)));
}

/* an end of edge feature s of b more than COMPLETE_TOL nearer feature o
 * of `other` than dist (the nearer end, the first on ties), or -1 */
static int nearer_end(const vrPosed *b, const vrSupportFeature *s, const vrPosed *other, const vrSupportFeature *o,
                      double *dist)
{
    int v[2], k, best = -1;
    segment_ends(b, s, &v[0], &v[1]);
    for (k = 0; k < 2; k++) {
        double d = to_segment(other, o, vrPosed_Vertex(b, v[k]));
        if (d < *dist - COMPLETE_TOL) *dist = d, best = v[k];
    }
    return best;
}

/* Two edges the segment formula takes as parallel are measured at the
 * middle of their overlap; tilted a hair, one of them comes nearer the
 * other at an end, and that end, not the middle, is the closest point
 * (from a walk that ended on that vertex the distance was the brute
 * force's, from one on the two edges 1.1 nm longer: other bits).  The
 * nearer end of either edge becomes a vertex feature; 1 if one did. */
static int reduce(const vrPosed *a, const vrPosed *b, vrCanon *c)
{
    double dist = c->dist;
    int va = nearer_end(a, &c->sa, b, &c->sb, &dist), vb = nearer_end(b, &c->sb, a, &c->sa, &dist);
    vrSupportFeature *s = vb >= 0 ? &c->sb : &c->sa;
    if (va < 0 && vb < 0) return 0;
    s->kind = VR_VERTEX;
    s->index = vb >= 0 ? vb : va;
    s->v.n = 0;
    return vrIntSet_Add(&s->v, s->index) ? -1 : 1;
}

/* normal and distance of vertex and edge features: two edges by their
 * cross product, else by the segment formula; 1 when that took two edges
 * as parallel */
static int measure(const vrPosed *a, const vrPosed *b, vrCanon *c)
{
    int edges = c->sa.kind == VR_EDGE && c->sb.kind == VR_EDGE;
    if (edges && edge_edge_normal(a, b, c)) return 0;
    point_features(a, b, c);
    return edges;
}

/* vertex and edge features: measured, parallel edges reduced to a nearer
 * end (reduce) and vertices completed (complete) until nothing changes,
 * at most REFINE_MAX times (a fixed bound: the same features and poses
 * end alike) */
#define REFINE_MAX 4
static int edges_and_vertices(const vrPosed *a, const vrPosed *b, vrCanon *c)
{
    int ca, cb, k;
    for (k = 0; k < REFINE_MAX; k++) {
        if (measure(a, b, c) && (ca = reduce(a, b, c)) != 0) {
            if (ca < 0) return -1;
            continue;
        }
        if ((ca = complete(a, &c->sa, c->qb)) < 0 || (cb = complete(b, &c->sb, c->qa)) < 0) return -1;
        if (!ca && !cb) return 0;
    }
    measure(a, b, c);
    return 0;
}

/* Steps 2-4 of the rule: support features along dir (a) and -dir (b),
 * then normal and distance from them. */
int vrCanon_Compute(const vrPosed *a, const vrPosed *b, vec3 dir, vrFeature fa, vrFeature fb, vrCanon *c)
{
    if (vrSupportFeature_Find(a, dir, fa, &c->sa) || vrSupportFeature_Find(b, vec3_neg(dir), fb, &c->sb)) return -1;
    if (c->sa.kind == VR_FACE) {
        c->n = vrPosed_FacePlane(a, c->sa.index, &c->ha);
        if (face_against(a, c->sa.index, c->n, c->ha, b, &c->sb, &c->qa, &c->qb, &c->dist)) return -1;
        c->hb = c->ha + c->dist;
    } else if (c->sb.kind == VR_FACE) {
        double hf;
        vec3 nb = vrPosed_FacePlane(b, c->sb.index, &hf);
        if (face_against(b, c->sb.index, nb, hf, a, &c->sa, &c->qb, &c->qa, &c->dist)) return -1;
        c->n = vec3_neg(nb);
        c->hb = -hf;
        c->ha = c->hb - c->dist;
    } else return edges_and_vertices(a, b, c);
    return 0;
}
