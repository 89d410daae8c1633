/* closest.c — the closest-feature walk (SPEC 3.1, thesis 3.2.1).
 *
 * V-Clip (B. Mirtich, "V-Clip: fast and robust polyhedral collision
 * detection", ACM TOG 17(3), 1998), written from the paper.  A feature
 * (vertex, edge, face) owns a Voronoi region bounded by planes, each plane
 * naming the neighbouring feature that lies beyond it (sec. 3; voronoi.c
 * holds the regions, this file the walk over them).  The walk
 * keeps one feature of each polyhedron; at every step it either proves the
 * pair closest (each closest point lies in the other feature's region,
 * Theorem 1) or moves one feature to a neighbour, never increasing the
 * distance and strictly decreasing it or the features' dimension (sec. 5).
 * Penetration shows itself as an edge piercing a face or as a vertex at a
 * local minimum beneath a face plane (sec. 5.3, 5.4).
 *
 * Where the closest points of a pair are unique (vertex-vertex, vertex-edge,
 * edge-edge; parallel edges take the middle of their overlap) they are tested
 * against the regions directly, as in Lin-Canny; Mirtich's clipping with
 * derivative checks is used where it is needed, for edge-face.
 *
 * Everything is evaluated in the body frames: a point is carried into the
 * frame of the polyhedron whose region it is tested against, with the one
 * relative transform computed per query.
 *
 * Floating point: a plane counts as violated only by more than `tol` metres,
 * so a point lying on a plane shared by two regions is accepted by both and
 * rounding cannot make the walk oscillate across it.  A hard step cap backs
 * the termination argument; past it an exhaustive search ends the query and
 * is counted in the cache (vrWalkCache.fallbacks).
 *
 * No static state: everything lives in the caller's cache and the stack.
 *   highest_face, closest_on_feature, steepest_edge   feature geometry
 *   vrWalk, to_other, vert_in_other  the pair, in side 0's frame (closest_walk.h)
 *   vertex_vertex .. edge_edge       one step per pair of feature types
 *   walk_step                        the dispatch
 *   walk_init, separated             a query's start; its check of the end
 *   pair_query                       the walk between two polyhedra
 * The exhaustive search past the step cap, with a final pair's points, is
 * closest_exhaustive.c's; the walk against a point (sphere centres),
 * closest_point.c's.
 */
#include <stdlib.h>

#include "closest_exhaustive.h"
#include "polyhedron.h"
#include "segment.h"
#include "voronoi.h"

enum { GO = VR_WALK_GO, DONE = VR_WALK_DONE, PENETRATING = VR_WALK_PENETRATING };

/* The edge of vertex v along which dot(dir, .) rises fastest, by more than
 * tol per edge (so an edge parallel to a face plane is no way down); -1 if none. */
static int steepest_edge(const vrPolyhedron *p, int v, vec3 dir, double tol)
{
    int k, best = -1, n = vrPolyhedron_VertDegree(p, v);
    double bestv = 0;
    for (k = 0; k < n; k++) {
        int e = p->vert_edge[p->vert_edge_start[v] + k];
        vec3 d = vec3_sub(p->vert[vrPolyhedron_OtherEnd(p, e, v)], p->vert[v]);
        double s = vec3_dot(dir, d), l2;
        if (s <= 0) continue;
        l2 = vec3_len2(d);
        if (s * s <= tol * tol * l2 || (best >= 0 && s * s <= bestv * l2)) continue;
        bestv = s * s / l2;
        best = e;
    }
    return best;
}

/* ---- the walk between two polyhedra (its state: closest_walk.h) -------- */

static int move(vrWalk *w, int i, vrFeature f)
{
    w->f[i] = f;
    return GO;
}

/* the pair is closest (Theorem 1); c0, c1 its closest points, frame 0 */
static int done(vrWalk *w, vec3 c0, vec3 c1)
{
    w->c[0] = c0;
    w->c[1] = c1;
    return DONE;
}

static int vertex_vertex(vrWalk *w)
{
    vrFeature nbr;
    vec3 x1 = vert_in_other(w, 1, w->f[1].index);
    if (vrVoronoi_Violation(w->p[0], w->f[0], x1, w->tol, &nbr, &w->slack2)) return move(w, 0, nbr);
    if (vrVoronoi_Violation(w->p[1], w->f[1], vert_in_other(w, 0, w->f[0].index), w->tol, &nbr, &w->slack2))
        return move(w, 1, nbr);
    return done(w, w->p[0]->vert[w->f[0].index], x1);
}

/* vertex on side i, edge on side 1-i */
static int vertex_edge(vrWalk *w, int i)
{
    int j = 1 - i;
    vec3 x = vert_in_other(w, i, w->f[i].index), q, qi;
    vrFeature nbr;
    if (vrVoronoi_Violation(w->p[j], w->f[j], x, w->tol, &nbr, &w->slack2)) return move(w, j, nbr);
    q = vrVoronoi_ClosestOnFeature(w->p[j], w->f[j], x);
    qi = to_other(w, j, q);
    if (vrVoronoi_Violation(w->p[i], w->f[i], qi, w->tol, &nbr, &w->slack2)) return move(w, i, nbr);
    /* side 0's points are in frame 0 already: the vertex (i = 0) or q (i = 1) */
    return i == 0 ? done(w, w->p[0]->vert[w->f[0].index], qi) : done(w, q, x);
}

/* Mirtich sec. 5.3: the vertex (x, frame of side j) lies beneath the face
 * plane and no edge of it climbs toward the plane.  Either every face plane
 * of j has x beneath it (penetration), or the walk jumps to the face whose
 * plane x is farthest above. */
static int local_minimum(vrWalk *w, int i, vec3 x)
{
    int j = 1 - i;
    double smax;
    int best = vrVoronoi_HighestFace(w->p[j], x, &smax);
    if (smax <= 0) return penetrating(w, smax, in_frame0(w, j, x));
    return move(w, j, vrFeature_Make(VR_FACE, best));
}

/* vertex on side i, face on side 1-i */
static int vertex_face(vrWalk *w, int i)
{
    int j = 1 - i, v = w->f[i].index, f = w->f[j].index, e;
    const vrPolyhedron *q = w->p[j];
    vec3 x = vert_in_other(w, i, v), n_i;
    vrFeature nbr;
    double h;
    if (vrVoronoi_Violation(q, w->f[j], x, w->tol, &nbr, &w->slack2)) return move(w, j, nbr);
    h = vrPolyhedron_FaceHeight(q, f, x);
    n_i = rotate_other(w, j, q->face_normal[f]);
    /* an edge of v leading toward the plane lowers |h| */
    e = steepest_edge(w->p[i], v, h >= 0 ? vec3_neg(n_i) : n_i, w->tol);
    if (e >= 0) return move(w, i, vrFeature_Make(VR_EDGE, e));
    if (h < 0) return local_minimum(w, i, x);
    x = vec3_madd(x, -h, q->face_normal[f]); /* its projection on the face, frame j */
    return i == 0 ? done(w, w->p[0]->vert[v], to_other(w, 1, x)) : done(w, x, vert_in_other(w, 1, v));
}

/* the boundary edge of face f nearest to segment t..h (frame of f) */
static vrFeature nearest_boundary_edge(const vrPolyhedron *p, int f, vec3 t, vec3 h)
{
    int k, s = p->face_start[f], m = p->face_start[f + 1] - s, best = 0;
    double bestd = HUGE_VAL;
    for (k = 0; k < m; k++) {
        vec3 a = p->vert[p->face_vert[s + k]], b = p->vert[p->face_vert[s + (k + 1 == m ? 0 : k + 1)]];
        double u, v, d;
        vrSegment_ClosestParams(t, h, a, b, &u, &v);
        d = vec3_dist(vec3_lerp(t, h, u), vec3_lerp(a, b, v));
        if (d < bestd) {
            bestd = d;
            best = k;
        }
    }
    return vrFeature_Make(VR_EDGE, p->face_edge[s + best]);
}

/* Edge on side i, face on side j (Mirtich sec. 5.4).  Never a final state:
 * the closest point of the face lies on its boundary, or the closest point of
 * the edge is an endpoint inside the prism, or the edge pierces the face.
 * Where V-Clip moves to the clipping plane's edge, we move to the boundary
 * edge nearest to E: the distance is unchanged by construction. */
static int edge_face(vrWalk *w, int i)
{
    int j = 1 - i, e = w->f[i].index, f = w->f[j].index;
    const vrPolyhedron *q = w->p[j];
    const int *ev = w->p[i]->edge_v[e];
    vec3 t = vert_in_other(w, i, ev[0]), h = vert_in_other(w, i, ev[1]);
    double lo, hi, dl, du, slope;
    if (!vrVoronoi_ClipToFace(q, f, t, h, &lo, &hi)) return move(w, j, nearest_boundary_edge(q, f, t, h));
    dl = vrPolyhedron_FaceHeight(q, f, vec3_lerp(t, h, lo));
    du = vrPolyhedron_FaceHeight(q, f, vec3_lerp(t, h, hi));
    if ((dl < 0 && du > 0) || (dl > 0 && du < 0)) {
        vec3 c = vec3_lerp(t, h, lo + (hi - lo) * dl / (dl - du));
        return penetrating(w, 0, in_frame0(w, j, c));
    }
    /* derivative of the distance |height| along t -> h */
    slope = vec3_dot(q->face_normal[f], vec3_sub(h, t));
    if (dl < 0 || (dl == 0 && du < 0)) slope = -slope;
    if (slope >= 0) return lo == 0 ? move(w, i, vrFeature_Make(VR_VERTEX, ev[0])) : move(w, j, nearest_boundary_edge(q, f, t, h));
    return hi == 1 ? move(w, i, vrFeature_Make(VR_VERTEX, ev[1])) : move(w, j, nearest_boundary_edge(q, f, t, h));
}

static int edge_edge(vrWalk *w)
{
    const int *e0 = w->p[0]->edge_v[w->f[0].index], *e1 = w->p[1]->edge_v[w->f[1].index];
    vec3 a0 = w->p[0]->vert[e0[0]], a1 = w->p[0]->vert[e0[1]];
    vec3 b0 = vert_in_other(w, 1, e1[0]), b1 = vert_in_other(w, 1, e1[1]), c0, c1;
    double s, t;
    vrFeature nbr;
    vrSegment_ClosestParams(a0, a1, b0, b1, &s, &t);
    c0 = vec3_lerp(a0, a1, s);
    c1 = vec3_lerp(b0, b1, t);
    if (vrVoronoi_Violation(w->p[0], w->f[0], c1, w->tol, &nbr, &w->slack2)) return move(w, 0, nbr);
    if (vrVoronoi_Violation(w->p[1], w->f[1], to_other(w, 0, c0), w->tol, &nbr, &w->slack2)) return move(w, 1, nbr);
    return done(w, c0, c1);
}

static int walk_step(vrWalk *w)
{
    w->slack2 = 0;
    switch (w->f[0].type * 3 + w->f[1].type) {
    case VR_VERTEX * 3 + VR_VERTEX: return vertex_vertex(w);
    case VR_VERTEX * 3 + VR_EDGE: return vertex_edge(w, 0);
    case VR_EDGE * 3 + VR_VERTEX: return vertex_edge(w, 1);
    case VR_VERTEX * 3 + VR_FACE: return vertex_face(w, 0);
    case VR_FACE * 3 + VR_VERTEX: return vertex_face(w, 1);
    case VR_EDGE * 3 + VR_EDGE: return edge_edge(w);
    case VR_EDGE * 3 + VR_FACE: return edge_face(w, 0);
    case VR_FACE * 3 + VR_EDGE: return edge_face(w, 1);
    default: /* face-face: the walk never makes it; from a foreign cache, take a vertex */
        return move(w, 0, vrFeature_Make(VR_VERTEX, w->p[0]->face_vert[w->p[0]->face_start[w->f[0].index]]));
    }
}

/* ---- entry points ------------------------------------------------------- */


/* Ra^T Rb, spelt out by columns of Rb: the walk's one 3x3 product a query,
 * without forming the transpose */
static mat33 relative_rotation(const mat33 *ra, const mat33 *rb)
{
    mat33 r;
    vec3 c0 = mat33_tmulv(ra, mat33_col(rb, 0)), c1 = mat33_tmulv(ra, mat33_col(rb, 1));
    vec3 c2 = mat33_tmulv(ra, mat33_col(rb, 2));
    r.m[0][0] = c0.x, r.m[0][1] = c1.x, r.m[0][2] = c2.x;
    r.m[1][0] = c0.y, r.m[1][1] = c1.y, r.m[1][2] = c2.y;
    r.m[2][0] = c0.z, r.m[2][1] = c1.z, r.m[2][2] = c2.z;
    return r;
}

static void walk_init(vrWalk *w, const vrPolyhedron *a, const vrPose *pa, const vrPolyhedron *b, const vrPose *pb,
                      const vrWalkCache *cache)
{
    w->p[0] = a;
    w->p[1] = b;
    w->R = relative_rotation(&pa->R, &pb->R);
    w->t = mat33_tmulv(&pa->R, vec3_sub(pb->p, pa->p));
    w->tol = vrClosest_Tolerance(a->r_out + b->r_out + vec3_maxabs(w->t)); /* a size, no sqrt needed */
    if (cache && cache->valid && vrFeature_Valid(a, cache->a) && vrFeature_Valid(b, cache->b)) {
        w->f[0] = cache->a;
        w->f[1] = cache->b;
    } else {
        w->f[0] = w->f[1] = vrFeature_Make(VR_VERTEX, 0);
    }
}

/* the distance between the bodies is at least this: their extents along
 * the unit direction u (frame 0) from a to b, each climbed from a vertex of
 * its final feature (usually no step) */
static double separation_along(const vrWalk *w, vec3 u)
{
    vec3 u1 = vec3_neg(rotate_other(w, 0, u));
    int top_a = vrPolyhedron_Climb(w->p[0], u, vrFeature_Vertex(w->p[0], w->f[0]), NULL);
    int top_b = vrPolyhedron_Climb(w->p[1], u1, vrFeature_Vertex(w->p[1], w->f[1]), NULL);
    return vec3_dot(u, w->t) - vec3_dot(u1, w->p[1]->vert[top_b]) - vec3_dot(u, w->p[0]->vert[top_a]);
}

/* two edges' unit cross product, pointing along d; zero for edges near
 * parallel */
static vec3 edges_normal(const vrWalk *w, vec3 d)
{
    const vrPolyhedron *a = w->p[0], *b = w->p[1];
    const int *ea = a->edge_v[w->f[0].index], *eb = b->edge_v[w->f[1].index];
    vec3 da = vec3_sub(a->vert[ea[1]], a->vert[ea[0]]);
    vec3 db = rotate_other(w, 1, vec3_sub(b->vert[eb[1]], b->vert[eb[0]]));
    vec3 n = vec3_cross(da, db);
    double l = vec3_len(n);
    if (!(l > 1e-3 * vec3_len(da) * vec3_len(db))) return vec3_zero();
    return vec3_scale(n, (vec3_dot(n, d) < 0 ? -1 : 1) / l);
}

/* Does a plane separate the bodies as far apart as the final pair's closest
 * points are (to 0.1 tol)?  A vertex over a face is measured along the
 * face's normal, and the vertex's edges were checked to rise: yes.  Else
 * the direction comes from the closest points, and the region tests let
 * pass an excess up to w->tol: at a gap g that tilts it by up to tol/g,
 * and a face of size D beyond the feature then reaches tol D/g past the
 * plane (two boxes of a stack overlapping by 2e-7 m ended on crossing
 * edges 1.8e-7 m apart, the direction off by 1.5e-6 rad).  When the
 * excess let pass, or rounding, could tilt it that far, each body's extent
 * along it is climbed; its rounding too grows as 1/g, so two edges' cross
 * product, exact, is tried as well. */
static int separated(const vrWalk *w)
{
    vec3 d = vec3_sub(w->c[1], w->c[0]), n;
    double g = vec3_len(d), want = g - 0.1 * w->tol, size = 2 * (w->p[0]->r_out + w->p[1]->r_out);
    if (w->f[0].type == VR_FACE || w->f[1].type == VR_FACE) return 1;
    if (!(g > 0)) return 1;   /* touching: contact.c decides those from a fixed start */
    if (g >= 1e-3 * size && w->slack2 * size * size <= 0.01 * w->tol * w->tol * g * g) return 1;
    if (separation_along(w, vec3_scale(d, 1 / g)) >= want) return 1;
    if (w->f[0].type != VR_EDGE || w->f[1].type != VR_EDGE) return 0;
    n = edges_normal(w, d);
    return vec3_len2(n) > 0 && separation_along(w, n) >= want;
}

/* the walk, or with `at_once` the exhaustive search without walking (2:
 * over every feature pair) */
static double pair_query(const vrPolyhedron *a, const vrPose *pa, const vrPolyhedron *b, const vrPose *pb,
                         vrWalkCache *cache, vec3 *ca, vec3 *cb, int *steps, int *penetrating_out, int at_once)
{
    vrWalk w;
    int n = 0, r = GO;
    walk_init(&w, a, pa, b, pb, cache);
    if (at_once) r = at_once == 2 ? vrWalk_ExhaustiveAll(&w) : vrWalk_Exhaustive(&w);
    while (r == GO && (r = walk_step(&w)) == GO)
        if (++n >= 8 && n >= vrClosest_StepCap(a) + vrClosest_StepCap(b)) {
            r = vrWalk_Exhaustive(&w);
            if (cache) cache->fallbacks++;
        }
    if (r == DONE && !at_once && !separated(&w)) {
        r = vrWalk_Exhaustive(&w);
        if (cache) cache->fallbacks++;
    }
    if (cache) {
        cache->a = w.f[0];
        cache->b = w.f[1];
        cache->valid = 1;
    }
    if (steps) *steps = n;
    if (penetrating_out) *penetrating_out = r == PENETRATING;
    if (r == PENETRATING) {
        if (ca) *ca = vrPose_apply(pa, w.pen_point);
        if (cb) *cb = vrPose_apply(pa, w.pen_point);
        return w.pen_dist;
    }
    if (ca) *ca = vrPose_apply(pa, w.c[0]);
    if (cb) *cb = vrPose_apply(pa, w.c[1]);
    return vec3_dist(w.c[0], w.c[1]);
}

double vrClosest_Walk(const vrPolyhedron *a, const vrPose *pa, const vrPolyhedron *b, const vrPose *pb,
                      vrWalkCache *cache, vec3 *ca, vec3 *cb, int *steps, int *penetrating)
{
    return pair_query(a, pa, b, pb, cache, ca, cb, steps, penetrating, 0);
}

double vrClosest_Exhaustive(const vrPolyhedron *a, const vrPose *pa, const vrPolyhedron *b, const vrPose *pb,
                            vrWalkCache *cache, vec3 *ca, vec3 *cb, int *penetrating)
{
    return pair_query(a, pa, b, pb, cache, ca, cb, NULL, penetrating, 1);
}

double vrClosest_ExhaustiveAll(const vrPolyhedron *a, const vrPose *pa, const vrPolyhedron *b, const vrPose *pb,
                               vrWalkCache *cache, vec3 *ca, vec3 *cb, int *penetrating)
{
    return pair_query(a, pa, b, pb, cache, ca, cb, NULL, penetrating, 2);
}
