/* bisect.c — the moment an impact (distance down to d) or a touch
 * (distance down to 0) happens inside a grid step: 48 halvings, the event
 * at the upper end of the final bracket (thesis 3.2.3, SPEC 3.2), or
 * fewer when a halving finds the distance at the level (VR_AT_LEVEL).
 * A halving whose answer the distance bounds of a measurement at either
 * end of the bracket prove (distbound.c) is not asked of the geometry.
 *   vrPair_Within    the test at one instant, with the bounds it gives
 *   decided          what the bounds say
 *   vrPair_Bisect    the halvings */
#include "owner_state.h"
#include "distbound.h"

#define BISECTIONS 48

/* how far from d the distance bounds must be to decide a halving: a
 * hundred times what they and the measured distance differ by in the
 * tests (below 1e-14 m for bodies 9 m from the origin a minute into a run,
 * below 1e-15 m near it).  Not lower: a minute into a run a time rounds
 * a 16 m/s body's position by 1e-13 m. */
#define BOUND_TOL 1e-12

/* the bisection's test: is the pair's distance at t at most level (d: an
 * impact; 0: touching)?  2: at the level (contact.h, VR_AT_LEVEL).  When
 * what was measured can bound the distance nearby (a gap and closest
 * points), *near (if not NULL) gets those bounds for times in [lo, hi]. */
int vrPair_Within(vrOwner *o, vrPair *p, double t, double level, double lo, double hi, vrDistBound *near)
{
    vrBody *A = o->body[p->a], *B = o->body[p->b];
    vrPose pa, pb;
    vrContact seen;
    int in;
    vrBody_ShapePose(A, t, &pa);
    vrBody_ShapePose(B, t, &pb);
    o->checks++;
    in = vrContact_Within(&A->shape, &pa, &B->shape, &pb, &p->cache, level, &seen);
    if (!near) return in;
    near->valid = 0;
    /* bounds from a measurement within a few tolerances of the level cannot
     * decide anything beside it: not worth making */
    if (seen.dist > 0 && fabs(seen.dist - level) > 4 * BOUND_TOL)
        vrDistBound_Make(near, A, &pa, B, &pb, t, seen.pa, seen.pb, 1, lo, hi);
    return in;
}

/* what the bounds from the bracket's two ends say about the distance at t */
static int decided(vrDistBound *const near[2], double t, double level)
{
    int k, say;
    for (k = 0; k < 2; k++)
        if ((say = vrDistBound_Decide(near[k], t, level, BOUND_TOL)) >= 0) return say;
    return -1;
}

/* the first time in (lo, hi] with distance <= level: BISECTIONS halvings,
 * the event at the upper end of the final bracket (SPEC 3.2), or at the
 * first halving whose distance is at the level (a decision of vroc's, man
 * vroc).  at_hi is the query at hi.  A halving whose answer the bounds
 * from a measurement at either end of the bracket prove (distbound.h) is
 * not asked of the geometry: the same answers, so the same bracket, from
 * a few walks.
 * NAN once the bracket is past `wanted` (an event found at this grid point
 * comes first): the event would be dropped, and this grid point's looks
 * rolled back, after the first is answered; the halvings left, where most
 * of the geometry is asked, would be for nothing (in a heap of a
 * thousand bodies, most bisections). */
double vrPair_Bisect(vrOwner *o, vrPair *p, double lo, double hi, const vrContact *at_hi, double level,
                     double wanted)
{
    const double lo0 = lo, hi0 = hi;
    /* the bounds from the measurements at lo and at hi, and a slot for the
     * next: a measurement takes the place of the end it moves by a swap of
     * pointers (a bound is some 700 bytes: not copied per halving) */
    vrDistBound slot[3], *near[2], *spare = &slot[2];
    vrPose pa, pb;
    int i, lo_tested = 0;
    near[0] = &slot[0], near[1] = &slot[1];
    near[0]->valid = near[1]->valid = 0;
    if (at_hi->dist > 0) {
        vrBody_ShapePose(o->body[p->a], hi, &pa);
        vrBody_ShapePose(o->body[p->b], hi, &pb);
        /* the query's closest points are canonical, not always points of
         * the bodies: its direction bounds from below only */
        vrDistBound_Make(near[1], o->body[p->a], &pa, o->body[p->b], &pb, hi, at_hi->pa, at_hi->pb, 0, lo0, hi0);
    }
    for (i = 0; i < BISECTIONS; i++) {
        double mid = lo + 0.5 * (hi - lo);
        int in;
        /* Once lo and hi are adjacent doubles the midpoint rounds to one of
         * them and the halvings left change nothing (late in a run, with
         * times of tens of seconds, a dozen of the 48): hi tests true, a lo
         * that was tested false does again, so neither is tested twice. */
        if (mid == hi || (mid == lo && lo_tested)) break;
        if ((in = decided(near, mid, level)) < 0) {
            vrDistBound *was;
            in = vrPair_Within(o, p, mid, level, lo0, hi0, spare);
            /* the bounds hold over the whole bracket: an end that moved
             * keeps the old ones when the new measurement gave none */
            if (spare->valid) was = near[in != 0], near[in != 0] = spare, spare = was;
        }
        if (in) {
            hi = mid;
            /* at the level to half a picometre: the halvings left would
             * only place the event closer in time than that gap resolves
             * (in a room of a thousand bodies, most of the geometry a
             * bisection asked; none of them decided by the bounds) */
            if (in == 2) break;
        } else {
            lo = mid, lo_tested = 1;
            /* lo tested apart: the event comes after it.  (An untested lo
             * may itself be the event, at the instant of one found here:
             * a tie, that pair order decides.) */
            if (lo >= wanted) return NAN;
        }
    }
    return hi;
}
