/* separation.c — the direction along which two posed polyhedra (or one
 * and a point) separate, from the walk's last features (thesis 3.2.1;
 * SPEC 3.2's determinism rule): the gap between their support planes
 * along a direction, the candidates (the walk's own direction, the
 * normals of the faces at its features, two edges' cross product), and
 * the one taken, the same whichever features the walk ended on.
 *   gap_along, vrGap_Along, vrGap_AlongFrom   the gap along a direction
 *   vrPick, pick_*                            the candidates and the one taken
 *   try_face, try_faces, try_edges            the candidates at the features
 *   vrGap_WalkDirection                       the direction */
#include "separation.h"
#include "polyhedron.h"
#include "shape.h"

/* the gap along u from the tops g's vertices are moved to: where a climb
 * ends, or (pure) the scan's answer, the first of tied tops, wherever the
 * climb started */
static double gap_along(vrGap *g, vec3 u, int pure)
{
    vec3 nu = vec3_neg(u), da = mat33_tmulv(&g->a->pose->R, u);
    double low_b;
    g->va = pure ? vrShape_TopVertex(g->a->p, da, g->va) : vrPolyhedron_Climb(g->a->p, da, g->va, NULL);
    if (g->b) {
        vec3 db = mat33_tmulv(&g->b->pose->R, nu);
        g->vb = pure ? vrShape_TopVertex(g->b->p, db, g->vb) : vrPolyhedron_Climb(g->b->p, db, g->vb, NULL);
    }
    low_b = g->b ? -vec3_dot(nu, vrPosed_Vertex(g->b, g->vb)) : vec3_dot(u, g->c);
    return low_b - vec3_dot(u, vrPosed_Vertex(g->a, g->va));
}

double vrGap_AlongFrom(vrGap *g, vec3 u) { return gap_along(g, u, 0); }

double vrGap_Along(const vrGap *g, vec3 u)
{
    vrGap from = *g;   /* the climbs start at g's vertices, which stay */
    return gap_along(&from, u, 1);
}

/* The candidates for the direction of separation, and the one taken: the
 * largest gap wins, but of those within rounding of it (`tie`) the first
 * in a fixed order, a's faces by index, then b's, then two edges' cross
 * product, then the walk's own direction.  Two faces a hair off parallel
 * were each the winner from some start of the walk (their gaps a rounding
 * apart, each walk trying them in its own order, and a climb stopping at
 * whichever of a face's tied vertices it met first), and the support sets
 * along the two normals then differed (tests/test_contact.c, boxes side
 * by side; man vroc, BUGS before 2026-12-06). */
#define PICK_MOST 16
enum { RANK_FACE_A, RANK_FACE_B, RANK_EDGES, RANK_WALKED };
typedef struct vrPick {
    const vrGap *g;
    double top, tie;          /* the largest gap so far; how far below it is a tie */
    int lone;                 /* the only candidate so far, its gap not measured (most calls
                                 have one: a corner on a face, or a closest edge or vertex) */
    vec3 lone_u;
    long long lone_order;
    int n;                    /* the measured candidates within tie of top: */
    vec3 u[PICK_MOST];
    double gap[PICK_MOST];
    long long order[PICK_MOST];
} vrPick;

static void pick_init(vrPick *k, const vrGap *g)
{
    k->g = g;
    k->top = -HUGE_VAL;
    k->tie = -1;              /* made at the first measurement */
    k->n = k->lone = 0;
}

/* a few roundings of positions as far out as the bodies reach */
static double tie_of(const vrGap *g)
{
    double far = vec3_len(g->a->pose->p) + g->a->p->r_out + (g->b ? vec3_len(g->b->pose->p) + g->b->p->r_out : vec3_len(g->c));
    return 1e-15 * (1 + far);
}

static long long pick_order(int rank, long long index) { return ((long long)rank << 40) + index; }

static void pick_measured(vrPick *k, vec3 u, double gap, long long order)
{
    int i, m = 0;
    if (k->tie < 0) k->tie = tie_of(k->g);
    if (!(gap >= k->top - k->tie)) return;
    if (gap > k->top) {
        k->top = gap;
        for (i = 0; i < k->n; i++)
            if (k->gap[i] >= gap - k->tie) k->u[m] = k->u[i], k->gap[m] = k->gap[i], k->order[m++] = k->order[i];
        k->n = m;
    }
    if (k->n == PICK_MOST) {  /* more ties than that: the last in the order goes */
        for (i = m = 0; i < k->n; i++)
            if (k->order[i] > k->order[m]) m = i;
        if (order > k->order[m]) return;
        k->n--, k->u[m] = k->u[k->n], k->gap[m] = k->gap[k->n], k->order[m] = k->order[k->n];
    }
    k->u[k->n] = u, k->gap[k->n] = gap, k->order[k->n++] = order;
}

/* the lone candidate measured: a second one has come */
static void pick_measure_lone(vrPick *k)
{
    if (k->lone) k->lone = 0, pick_measured(k, k->lone_u, vrGap_Along(k->g, k->lone_u), k->lone_order);
}

/* a candidate: measured once there are two */
static void pick_add(vrPick *k, vec3 u, long long order)
{
    int i;
    /* a face at a vertex comes once with each of its two edges there */
    if (k->lone && order == k->lone_order) return;
    for (i = 0; i < k->n; i++)
        if (k->order[i] == order) return;
    if (k->n == 0 && !k->lone && k->top == -HUGE_VAL) {
        k->lone = 1, k->lone_u = u, k->lone_order = order;
        return;
    }
    pick_measure_lone(k);
    pick_measured(k, u, vrGap_Along(k->g, u), order);
}

/* the first in the order among the ties; zero when there was none */
static vec3 pick_taken(const vrPick *k)
{
    int i, m = 0;
    if (k->lone) return k->lone_u;
    if (k->n == 0) return vec3_zero();
    for (i = 1; i < k->n; i++)
        if (k->order[i] < k->order[m]) m = i;
    return k->u[m];
}

/* face of x, when its normal times sign is within min_dot of `near`
 * (near_x: sign times near in x's frame, where the normals are) */
static void try_face(const vrPosed *x, int face, double sign, vec3 near_x, double min_dot, vrPick *k)
{
    if (vec3_dot(x->p->face_normal[face], near_x) < min_dot) return;
    pick_add(k, vec3_scale(vrPose_rotate(x->pose, x->p->face_normal[face]), sign),
             pick_order(sign > 0 ? RANK_FACE_A : RANK_FACE_B, face));
}

/* the normals (times sign) of the faces at feature f of x, among those
 * whose dot product with `near` is at least min_dot */
static void try_faces(const vrPosed *x, vrFeature f, double sign, vec3 near, double min_dot, vrPick *k)
{
    const vrPolyhedron *p = x->p;
    vec3 near_x = mat33_tmulv(&x->pose->R, vec3_scale(near, sign));
    int i, j, lo = f.type == VR_VERTEX ? p->vert_edge_start[f.index] : 0;
    int hi = f.type == VR_VERTEX ? p->vert_edge_start[f.index + 1] : 1;
    if (f.type == VR_FACE) {
        try_face(x, f.index, sign, near_x, min_dot, k);
        return;
    }
    for (i = lo; i < hi; i++)
        for (j = 0; j < 2; j++) try_face(x, p->edge_f[f.type == VR_VERTEX ? p->vert_edge[i] : f.index][j], sign, near_x, min_dot, k);
}

/* The cross product of edges ea of a and eb of b, the way it separates.
 * Crossing edges a hair apart: the direction between the closest points
 * is off by 1e-16 m / gap (7e-9 rad at 1.4e-8 m), which tilts a 26 cm edge
 * 2e-9 m, beyond SUPPORT_TOL, so the edge's lower end alone was taken as
 * b's support and the distance came out 0.21 m for two touching boxes;
 * the cross product is exact. */
static void try_edges(const vrGap *g, int ea, int eb, vec3 near, double min_dot, vrPick *k)
{
    const vrPolyhedron *pa = g->a->p, *pb = g->b->p;
    vec3 da = vrPose_rotate(g->a->pose, vec3_sub(pa->vert[pa->edge_v[ea][1]], pa->vert[pa->edge_v[ea][0]]));
    vec3 db = vrPose_rotate(g->b->pose, vec3_sub(pb->vert[pb->edge_v[eb][1]], pb->vert[pb->edge_v[eb][0]]));
    vec3 u = vec3_cross(da, db);
    double gu, gn;
    if (vec3_len2(u) <= VR_PARALLEL_SIN2 * vec3_len2(da) * vec3_len2(db)) return;
    u = vec3_normalize(u);
    if (fabs(vec3_dot(u, near)) < min_dot) return;
    gu = vrGap_Along(g, u);
    gn = vrGap_Along(g, vec3_neg(u));
    if (gn > gu) u = vec3_neg(u), gu = gn;
    pick_measure_lone(k);
    pick_measured(k, u, gu, pick_order(RANK_EDGES, (long long)ea * pb->ne + eb));
}

/* Direction of separation at the walk's final features fa, fb (fb unused
 * for a point): where one is a face, its normal against the normals of
 * the other's faces at its feature (exact however small the gap); else the
 * direction between the closest points, against which the normals of the
 * faces at the features (and two edges' cross product) compete: the best
 * separating one wins (vrPick: ties by a fixed order).  Below GAP_FUZZ
 * that direction carries rounding of order 1e-16 m / gap (a plate 1e-12 m
 * above a table, walked to a pair of parallel edges, must still find the
 * table's face).  Above it, parallel edges of faces that face each other
 * tilt it for real: two 0.3 m cubes side by side 1 mm apart, one 3.4e-11
 * m lower than the other, walked to their top edges, gave a direction
 * 3.4e-8 rad off the faces' normal, along which the faces' far edges stand
 * 1e-8 m out, beyond SUPPORT_TOL: the supports were a's top edge and b's
 * bottom edge, and the distance came out 0.3 m with a vertical normal (the
 * pair left the envelope and the island).  Along the exact closest
 * direction the gap is the distance and along any other at most that, so
 * a face normal wins only where it is (within rounding) a closest
 * direction too; above GAP_FUZZ only those within NEAR_DOT of the
 * direction are measured (a corner or an edge that truly is closest has
 * none: no cost there). */
#define GAP_FUZZ 1e-6
#define NEAR_DOT (1 - 1e-6)
vec3 vrGap_WalkDirection(const vrGap *g, vrFeature fa, vrFeature fb, vec3 ca, vec3 cb, double dw)
{
    vec3 best, walked;
    double min_dot;
    vrPick k;
    pick_init(&k, g);
    if (fa.type == VR_FACE || (g->b && fb.type == VR_FACE)) {
        int on_a = fa.type == VR_FACE;
        walked = on_a ? vrPose_rotate(g->a->pose, g->a->p->face_normal[fa.index])
                      : vec3_neg(vrPose_rotate(g->b->pose, g->b->p->face_normal[fb.index]));
        pick_add(&k, walked, on_a ? pick_order(RANK_FACE_A, fa.index) : pick_order(RANK_FACE_B, fb.index));
        if (!on_a) try_faces(g->a, fa, 1, walked, NEAR_DOT, &k);   /* the other's faces at its feature */
        else if (g->b) try_faces(g->b, fb, -1, walked, NEAR_DOT, &k);
        return pick_taken(&k);
    }
    walked = vec3_normalize(vec3_sub(cb, ca));
    min_dot = dw >= GAP_FUZZ * (1 + g->a->p->r_out + (g->b ? g->b->p->r_out : 0)) ? NEAR_DOT : -2;
    /* closest points that coincide (crossing edges 3e-17 m apart) give no
     * direction at all: the features' own then win whatever their gap */
    if (vec3_len2(walked) > 0) pick_add(&k, walked, pick_order(RANK_WALKED, 0));
    if (g->b && fa.type == VR_EDGE && fb.type == VR_EDGE) try_edges(g, fa.index, fb.index, walked, min_dot, &k);
    try_faces(g->a, fa, 1, walked, min_dot, &k);
    if (g->b) try_faces(g->b, fb, -1, walked, min_dot, &k);
    best = pick_taken(&k);
    if (vec3_len2(best) == 0) best = vrUnitOrUp(vec3_sub(g->b ? g->b->pose->p : g->c, g->a->pose->p));
    return best;
}
