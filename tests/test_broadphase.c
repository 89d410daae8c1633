/* test_broadphase.c — the bodies an event's box meets (vrBroad_Meeting)
 * are exactly those a look at every body finds, however the events rebox
 * bodies within a frame, and the frame start meets every overlapping pair
 * once (but two static bodies, which make no pair): with the sorted sweep
 * and with the box trees (broad_tree.c). */
#include <stdlib.h>
#include <string.h>
#include "test.h"
#include "broadphase.h"
#include "scene.h"

#define TEST_LCG_SEED 4242ULL
#include "test_lcg.h"

#define NB 240
#define NSTATIC 24

static vrBody body[NB];
static vrBody *ptr[NB];
static vrFlight flight;

static void make_spheres(void)
{
    int i;
    flight.accel = vec3_make(0, 0, -9.8);
    flight.max_linear = 16;
    flight.max_angular = 100;
    for (i = 0; i < NB; i++) {
        vrBody *b = &body[i];
        vrScene_SphereBody(b, i, 0.1 + 0.2 * uni(), i < NSTATIC);
        vrBody_Anchor(b, 0, vec3_add(vec3_make(0, 0, 5), rvec(5)), i < NSTATIC ? vec3_zero() : rvec(3),
                      quat_identity(), vec3_zero(), &flight);
        ptr[i] = b;
    }
    /* two pieces of furniture that overlap (static: no pair) */
    vrBody_Anchor(&body[1], 0, vec3_add(body[0].m.x0, vec3_make(0.1, 0, 0)), vec3_zero(), quat_identity(), vec3_zero(),
                  &flight);
}

typedef struct { unsigned char seen[NB]; int n; } Found;

static void found(void *ctx, int y)
{
    Found *f = ctx;
    f->seen[y]++;
    f->n++;
}

/* Meeting(id) against every body: each overlapping (or boxless) body
 * once, no other, never id itself */
static int meeting_is_exact(vrBroadphase *bp, int id)
{
    Found f;
    int y;
    memset(&f, 0, sizeof f);
    ENSURE(vrBroad_Meeting(bp, id, found, &f) == 0);
    for (y = 0; y < NB; y++) {
        int meets = y != id && !vrBroad_Apart(&bp->box[id], &bp->box[y]);
        ENSURE_MSG(f.seen[y] == meets, "body %d with %d: seen %d times, meets %d", id, y, f.seen[y], meets);
    }
    return 0;
}

static int pairs_met, pairs_wrong;
static unsigned char met[NB][NB];
/* each pair once, in order (x < y) */
static void count_pair(void *ctx, int x, int y)
{
    (void)ctx;
    pairs_met++;
    if (x >= y || met[x][y]++) pairs_wrong++;
}
static void no_box(void *ctx, int id) { (void)ctx, (void)id; }

/* the pairs the sweep must meet: overlapping, not both static (the
 * first NSTATIC bodies) */
static int overlapping_pairs(vrBroadphase *bp)
{
    int x, y, n = 0;
    for (x = 0; x < NB; x++)
        for (y = x + 1; y < NB; y++) {
            int want = y >= NSTATIC && !vrBroad_Apart(&bp->box[x], &bp->box[y]);
            if (met[x][y] != want) pairs_wrong++;
            n += want;
        }
    return n;
}

/* Events within two frames re-anchor random bodies with new velocities
 * (some of them boxless: anchored past the frame's end), which moves their
 * boxes far along the sorted list; after each, a random body's meeting
 * set is checked. */
static int meeting_finds_exactly_the_overlapping_boxes(vrBroadKind kind)
{
    vrBroadphase bp;
    int frame, k, met_total = 0;
    make_spheres();
    vrBroad_Init(&bp);
    vrBroad_SetKind(&bp, kind);
    ENSURE(vrBroad_Reserve(&bp, NB) == 0);
    vrBroad_SetEnvelope(&bp, 0.01);
    ENSURE(vrBroad_Meeting(&bp, 0, found, NULL) == -1);      /* no frame yet: no list */
    for (frame = 0; frame < 2; frame++) {
        double t0 = 0.1 * frame, T = t0 + 0.1;
        pairs_met = pairs_wrong = 0;
        memset(met, 0, sizeof met);
        ENSURE(vrBroad_NewFrame(&bp, ptr, NB, t0, T, count_pair, no_box, NULL) == 0);
        ENSURE(pairs_met == overlapping_pairs(&bp) && pairs_met > 20 && pairs_wrong == 0);
        ENSURE(vrBroad_CanMeet(&bp));
        for (k = 0; k < 1500; k++) {
            double t = t0 + 0.1 * (k + 1) / 1501.0;
            int id = NSTATIC + (int)(uni() * (NB - NSTATIC)), q = (int)(uni() * NB);
            vrBody *b = &body[id];
            vrPose p;
            vrBody_Pose(b, t, &p);
            /* one in fifty anchored beyond the frame: no box until the next */
            vrBody_Anchor(b, k % 50 == 7 ? T + 1 : t, p.p, rvec(k % 3 ? 4 : 12), quat_identity(), vec3_zero(),
                          &flight);
            bp.t0 = t;
            vrBroad_Rebox(&bp, ptr, id);
            if (meeting_is_exact(&bp, q) || meeting_is_exact(&bp, id)) return 1;
            met_total += !vrBroad_Apart(&bp.box[id], &bp.box[q]);
        }
        /* the boxless bodies are anchored again inside the next frame */
        for (k = NSTATIC; k < NB; k++)
            if (body[k].m.t0 > T) {
                vrPose p;
                vrBody_Pose(&body[k], body[k].m.t0, &p);
                vrBody_Anchor(&body[k], T, p.p, vec3_zero(), quat_identity(), vec3_zero(), &flight);
            }
    }
    printf("    %d of the checked bodies met the rebox's\n", met_total);
    ENSURE(met_total > 10);
    vrBroad_BodyChanged(&bp, 3);            /* bodies came or went: no list until the next frame */
    ENSURE(vrBroad_Meeting(&bp, 0, found, NULL) == -1);
    vrBroad_Free(&bp);
    return 0;
}

static int test_meeting_finds_exactly_the_overlapping_boxes(void)
{
    return meeting_finds_exactly_the_overlapping_boxes(VR_BROAD_SWEEP);
}

static int test_tree_meeting_finds_exactly_the_overlapping_boxes(void)
{
    return meeting_finds_exactly_the_overlapping_boxes(VR_BROAD_TREE);
}

static const vrTest tests[] = {
    TEST(test_meeting_finds_exactly_the_overlapping_boxes),
    TEST(test_tree_meeting_finds_exactly_the_overlapping_boxes),
};

const vrTestSuite vrSuite_Broadphase = {"broadphase", tests, TEST_COUNT(tests), NULL, NULL, 0};
