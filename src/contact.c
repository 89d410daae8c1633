/* contact.c — distance, normal and contact region of a posed pair of
 * shapes: the entry points of contact.h (SPEC 2 "Contact region", SPEC 3.2
 * determinism rules, thesis 3.2.1).
 *
 * Polyhedra: the walk (closest.c) gives a direction, the canonical features
 * along it (canonical.c) the distance, normal and closest points, and, when
 * asked, the region (region.c); the result is a pure function of (shapes,
 * poses): the cache buys speed only.  Whether a contact within rounding of
 * distance 0 counts as touching or overlapping is decided by a walk from a
 * fixed start (TOUCH_TOL); overlapping polyhedra go to libccd
 * (penetration.c) unless they only touch (SHALLOW_TOL).  Spheres collide as
 * true spheres (sphere.c).
 *   set_result                  dist, n, pa, pb of a result
 *   gap_bound, touching_axis    the touch that libccd would see as overlap
 *   touching_features
 *   penetration_contact         the overlap: libccd, or a shallower face axis
 *   poly_finish, poly_contact   two polyhedra after the walk; with it
 *   sphere_contact              a sphere against anything
 *   contact                     the dispatch
 */
#include <string.h>

#include <stdlib.h>
#include "canonical.h"
#include "separation.h"
#include "face_groups.h"
#include "contact.h"
#include "penetration.h"
#include "sphere.h"

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
 * libccd's.  Bodies resting on each other may sink this far into each
 * other (SPEC 7: islands prevent overlap, they do not push out what is
 * left), and keep their whole contact region meanwhile. */
#define SHALLOW_TOL VR_SHALLOW_OVERLAP

/* Upper bounds on the gap along each face's normal.  The gap along u is
 * b's lowest height along u less a's highest: at most u.(x_b - x_a) for
 * any point x_b of b and x_a of a.  For a face of a, a vertex of the face
 * (a's highest along its normal) and on b's side the better of the walk's
 * point (a point of both shapes in an overlap, the closest point of a
 * touch) and the walk's vertex; for a face of b the same, sides swapped.
 * Measured in the face's own body frame against its plane (no higher
 * than a's highest point along it): a dot product a point.  A bound's
 * rounding does not change the answer: the winning face's bound is above
 * its gap, so above the floor, however it rounds (touching_axis). */
typedef struct { vec3 other[2]; } vrFaceBound;

static vrFaceBound face_bound(const vrPosed *x, vec3 walk_point, vec3 walk_vertex)
{
    vrFaceBound fb;
    fb.other[0] = vrPose_invapply(x->pose, walk_point);
    fb.other[1] = vrPose_invapply(x->pose, walk_vertex);
    return fb;
}

static double gap_bound(const vrFaceBound *fb, const vrPolyhedron *p, int f)
{
    vec3 n = p->face_normal[f];
    return vr_min(vec3_dot(n, fb->other[0]), vec3_dot(n, fb->other[1])) - p->face_offset[f];
}

/* what the walk's points and the bounds' own rounding may be off by (m):
 * far above both (1e-15 m a metre from the origin), far below any gap a
 * face that could win differs from the best by */
#define BOUND_SLACK 1e-9

static vec3 face_axis(const vrGap *g, int side, int f)
{
    const vrPosed *x = side ? g->b : g->a;
    vec3 u = vrPose_rotate(x->pose, x->p->face_normal[f]);
    return side ? vec3_neg(u) : u;
}

/* the face normal (a's, or minus b's) along which a and b are farthest
 * apart, and that gap; a's first face on a tie.  A face whose bound
 * (gap_bound) lies below the largest gap measured so far (the face with
 * the best bound's, first) cannot win and is not measured: the same answer as measuring every face, from
 * a few support climbs instead of two for every face of both shapes (a
 * superquadric's hundreds, at every halving of a touch's bisection).  A
 * big hull's faces are bounded a group at a time (face_groups.h), so that
 * only the groups facing the other shape are looked into: the same faces
 * found, and measured in the same order. */
/* the bounds of the first this many faces (a's, then b's) are kept from
 * the first pass for the second, not made again: most shapes have fewer */
#define KEPT_BOUNDS 512
/* candidates of a grouped hull measured in face order; more: every face looked at */
#define CANDIDATES_MOST 8192

/* the best bound of all faces so far, as (bound, then the lower k) */
typedef struct { double top; int side, f, k; } vrTopBound;

static void consider(vrTopBound *t, double ub, int side, int f, int k)
{
    if (ub > t->top || (ub == t->top && k < t->k)) t->top = ub, t->side = side, t->f = f, t->k = k;
}

/* each group's bound on its faces' gap bounds (gb[j]: group j's), made
 * once for both passes */
static void group_bounds(const vrFaceGroups *gs, const vrFaceBound *fb, double *gb)
{
    int j;
    for (j = 0; j < gs->n; j++)
        gb[j] = vr_min(vrFaceGroup_Bound(&gs->group[j], fb->other[0]), vrFaceGroup_Bound(&gs->group[j], fb->other[1]));
}

/* the best bound of one side's faces (k0: its first face's k; gb: its
 * groups' bounds, when it has groups) */
static void best_bound(const vrPolyhedron *p, const vrFaceBound *fb, const double *gb, int side, int k0,
                       vrTopBound *t, double *kept)
{
    const vrFaceGroups *gs = p->groups;
    int f, i, j, first = 0;
    if (!gs) {
        for (f = 0; f < p->nf; f++) {
            double ub = gap_bound(fb, p, f);
            if (k0 + f < KEPT_BOUNDS) kept[k0 + f] = ub;
            consider(t, ub, side, f, k0 + f);
        }
        return;
    }
    for (i = 1; i < gs->n; i++)   /* the likeliest group first: its top skips most others */
        if (gb[i] > gb[first]) first = i;
    for (j = -1; j < gs->n; j++) {
        int at = j < 0 ? first : j;
        const vrFaceGroup *g = &gs->group[at];
        if (j == first || gb[at] < t->top) continue;
        for (i = 0; i < g->n; i++) {
            f = gs->face[g->start + i];
            consider(t, gap_bound(fb, p, f), side, f, k0 + f);
        }
    }
}

static int cmp_int(const void *x, const void *y) { return *(const int *)x - *(const int *)y; }

/* a grouped side's faces whose bound reaches `floor`, ascending; -1 when
 * there are more than CANDIDATES_MOST */
static int candidates(const vrPolyhedron *p, const vrFaceBound *fb, const double *gb, double floor, int *out)
{
    const vrFaceGroups *gs = p->groups;
    int n = 0, i, j;
    for (j = 0; j < gs->n; j++) {
        const vrFaceGroup *g = &gs->group[j];
        if (gb[j] < floor) continue;
        for (i = 0; i < g->n; i++) {
            int f = gs->face[g->start + i];
            if (gap_bound(fb, p, f) < floor) continue;
            if (n == CANDIDATES_MOST) return -1;
            out[n++] = f;
        }
    }
    if (n > 1) qsort(out, (size_t)n, sizeof *out, cmp_int);   /* (a count of none or one is sorted) */
    return n;
}

static vec3 touching_axis(const vrGap *g, vec3 ca, vec3 cb, double *gap)
{
    vrFaceBound fb[2];
    vrGap warm = *g;   /* its climbs start where the last one ended */
    vrTopBound t;
    vec3 best;
    double floor_gap, top_gap, kept[KEPT_BOUNDS], gb[2][VR_FACE_GROUPS_MOST];
    int side, f, k, best_k, nf_a = g->a->p->nf, cand[CANDIDATES_MOST];
    fb[0] = face_bound(g->a, cb, vrPosed_Vertex(g->b, g->vb));
    fb[1] = face_bound(g->b, ca, vrPosed_Vertex(g->a, g->va));
    if (g->a->p->groups) group_bounds(g->a->p->groups, &fb[0], gb[0]);
    if (g->b->p->groups) group_bounds(g->b->p->groups, &fb[1], gb[1]);
    t.top = -HUGE_VAL, t.side = t.f = 0, t.k = -1;
    best_bound(g->a->p, &fb[0], gb[0], 0, 0, &t, kept);
    best_bound(g->b->p, &fb[1], gb[1], 1, nf_a, &t, kept);
    top_gap = vrGap_AlongFrom(&warm, face_axis(g, t.side, t.f));
    floor_gap = top_gap - BOUND_SLACK;
    *gap = top_gap, best = face_axis(g, t.side, t.f), best_k = t.k;
    for (side = 0; side < 2; side++) {
        const vrPolyhedron *p = side ? g->b->p : g->a->p;
        int k0 = side ? nf_a : 0, n = p->groups ? candidates(p, &fb[side], gb[side], floor_gap, cand) : -1, i;
        for (i = 0; i < (n >= 0 ? n : p->nf); i++) {
            vec3 u;
            double h, ub;
            f = n >= 0 ? cand[i] : i;
            k = k0 + f;
            /* NOLINTNEXTLINE(clang-analyzer-core.UndefinedBinaryOperatorResult): the first pass wrote kept[k], the same faces in the same order */
            ub = k < KEPT_BOUNDS && !p->groups ? kept[k] : gap_bound(&fb[side], p, f);
            if (k == best_k || ub < *gap - BOUND_SLACK) continue;
            u = face_axis(g, side, f);
            h = vrGap_AlongFrom(&warm, u);
            if (h > *gap || (h == *gap && k < best_k)) *gap = h, best = u, best_k = k;
        }
    }
    return best;
}

/* Shapes that touch by the walk: the canonical features along the
 * touching axis, when the shapes are no more than SHALLOW_TOL apart or
 * into each other along it; else -1.  No libccd here: moving either shape
 * by the overlap along that axis separates them, so they are no deeper
 * than that inside each other (an MPR asked as well, at every halving of a
 * touch's bisection, was a quarter of a scene's time). */
static int touching_features(vrGap *g, vec3 ca, vec3 cb, vrFeature fa, vrFeature fb, vrCanon *c)
{
    double gap;
    vec3 axis = touching_axis(g, ca, cb, &gap);
    if (!(fabs(gap) <= SHALLOW_TOL)) return -1;
    if (vrCanon_Compute(g->a, g->b, axis, fa, fb, c) != 0 || !(fabs(c->dist) <= SHALLOW_TOL)) return -1;
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
                               const vrGap *g, vec3 ca, vec3 cb, vrContact *out)
{
    double depth, gap;
    vec3 dir, pos, axis;
    if (vrPenetration(a, pa, b, pb, &depth, &dir, &pos) == 0) {
        axis = touching_axis(g, ca, cb, &gap);
        if (gap < 0 && -gap < depth) set_result(out, gap, axis, pos, pos);
        else set_result(out, -depth, vrUnitOrUp(dir), pos, pos);
    } else {
        pos = vec3_lerp(ca, cb, 0.5);
        set_result(out, 0, vrUnitOrUp(vec3_sub(pb->p, pa->p)), pos, pos);
    }
    if (d >= 0) {
        out->npoints = 1;
        out->point[0] = pos;
        out->gap[0] = out->dist;
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
    vrPosed ba, bb;
    vrCanon c;
    vrGap g;
    vrWalkCache fresh;
    int rc;
    if (pen || !(dw > TOUCH_TOL)) {
        memset(&fresh, 0, sizeof fresh);
        cache = &fresh;
        dw = vrClosest_Walk(a->poly, pa, b->poly, pb, cache, &ca, &cb, NULL, &pen);
    }
    ba.p = a->poly, ba.pose = pa, bb.p = b->poly, bb.pose = pb;
    vrCanon_Init(&c);
    g.a = &ba, g.b = &bb, g.va = vrFeature_Vertex(ba.p, cache->a), g.vb = vrFeature_Vertex(bb.p, cache->b);
    if (pen || !(dw > 0)) {
        rc = touching_features(&g, ca, cb, cache->a, cache->b, &c);
    } else {
        rc = vrCanon_Compute(&ba, &bb, vrGap_WalkDirection(&g, cache->a, cache->b, ca, cb, dw), cache->a, cache->b, &c);
        if (rc == 0 && !(c.dist > 0)) { /* the canonical features touch */
            vrCanon_Free(&c);
            vrCanon_Init(&c);
            rc = touching_features(&g, ca, cb, cache->a, cache->b, &c);
        }
    }
    if (rc != 0) {   /* an overlap (or out of memory: libccd then too) */
        vrCanon_Free(&c);
        return penetration_contact(a, pa, b, pb, d, &g, ca, cb, out);
    }
    set_result(out, c.dist, c.n, c.qa, c.qb);
    if (d >= 0 && c.dist <= d) rc = vrRegion_Points(&ba, &bb, &c, d, out->point, out->gap, &out->npoints);
    vrCanon_Free(&c);
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

/* A true sphere against anything: measure from the sphere's centre (b's
 * when both are spheres), then orient a -> b. */
static int sphere_contact(const vrShape *a, const vrPose *pa, const vrShape *b, const vrPose *pb, double d,
                          vrWalkCache *cache, vrContact *out)
{
    int sb = b->kind == VR_SHAPE_SPHERE, rc = 0;
    const vrShape *s = sb ? b : a, *o = sb ? a : b;
    const vrPose *ps = sb ? pb : pa, *po = sb ? pa : pb;
    vec3 sp, pos, at;
    vrNear nr;
    double dist;
    out->walk_steps = 0;
    if (o->kind == VR_SHAPE_SPHERE) {
        nr = vrNear_Sphere(po->p, o->radius, ps->p);
    } else if (o->kind == VR_SHAPE_BOX) {
        nr = vrNear_Box(o, po, ps->p);
    } else if (!o->poly || vrNear_Poly(o->poly, po, ps->p, cache, &out->walk_steps, &nr)) {
        return -1;
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
        out->gap[0] = dist;
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

/* 0: dist above d; 1: at most d; 2: at d (within VR_AT_LEVEL below it) */
static int at_level(double dist, double d)
{
    return dist > d ? 0 : dist >= d - VR_AT_LEVEL ? 2 : 1;
}

/* How far above a level the walk's distance must be to answer alone:
 * VR_QUICK_TOL and the walk's own slack.  The walk stops within its region
 * tolerance (vrClosest_Tolerance of the pair's size) of the
 * closest features; where a face lies a hair off parallel to an edge that
 * is a place metres along the edge, a little above the true distance,
 * which the canonical distance measures (the edit fuzzer's seed 6785: a
 * prism's bottom face tilted 4e-12 rad over a floor's edge, the walk
 * 1.009e-11 or 0.974e-11 m above the level by its start, 3.4e-13 apart,
 * at a size of 4 m).  Below a level VR_QUICK_TOL is enough: the walk's
 * distance is between points of the bodies, never below the true one, and
 * the canonical distance lies above the true one by at most 1e-12 m
 * (canonical.c's COMPLETE_TOL). */
static double above_walk_slack(const vrPolyhedron *a, const vrPose *pa, const vrPolyhedron *b, const vrPose *pb)
{
    /* the offset's length bounds the walk's own (its largest coordinate in a's frame) */
    return VR_QUICK_TOL + 2 * vrClosest_Tolerance(a->r_out + b->r_out + vec3_len(vec3_sub(pb->p, pa->p)));
}

/* One walk: its own distance when that is clear of d, else the canonical
 * distance finished from the same walk (a second walk from where the first
 * ended would only confirm it).  Clear below d by VR_QUICK_TOL, above it
 * by above_walk_slack: otherwise a walk a little above d from one start
 * and a little below from another gave two answers (seed 6785, whose run
 * read from a save parted from the one that saved). */
int vrContact_Within(const vrShape *a, const vrPose *pa, const vrShape *b, const vrPose *pb,
                     vrWalkCache *cache, double d, vrContact *seen)
{
    vrContact c;
    vec3 ca, cb;
    int pen;
    double dw;
    if (!seen) seen = &c;
    if (a->kind == VR_SHAPE_SPHERE || b->kind == VR_SHAPE_SPHERE || !a->poly || !b->poly || !cache) {
        seen->dist = INFINITY;   /* a shape without its polyhedron is measured as far: never within */
        contact(a, pa, b, pb, -1, cache, seen);
        return at_level(seen->dist, d);
    }
    dw = vrClosest_Walk(a->poly, pa, b->poly, pb, cache, &ca, &cb, NULL, &pen);
    seen->dist = pen ? fmin(dw, 0.0) : dw;
    seen->pa = ca;
    seen->pb = cb;
    if (!pen && dw > 0 && (dw < d - VR_QUICK_TOL || dw > d + above_walk_slack(a->poly, pa, b->poly, pb)))
        return dw < d;
    /* Touching or overlapping by the walk, asked about a level above any
     * touch: whatever poly_finish would find (a touch within SHALLOW_TOL,
     * libccd's overlap, a walk from a fixed start a rounding apart) is at
     * most SHALLOW_TOL, so the answer is yes without it.  Bisections of
     * bodies resting on each other asked this at every halving, each
     * answer a separating-axis test over both shapes' faces and an MPR. */
    if ((pen || !(dw > TOUCH_TOL)) && d > SHALLOW_TOL) return 1;
    c.dist = dw;
    c.npoints = 0;
    poly_finish(a, pa, b, pb, -1, cache, dw, ca, cb, pen, &c);
    return at_level(c.dist, d);
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
