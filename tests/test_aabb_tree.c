/* test_aabb_tree.c — the box tree (src/aabb_tree.c) against a look at
 * every pair of boxes, and the broadphase on box trees (broadphase =
 * tree) against the sorted sweep: whole runs give the same bits.
 *   1. random boxes through inserts, removes, refits, moves of every leaf
 *      and rebuilds: the overlapping pairs, the boxes a query meets and the
 *      pairs across two trees are exactly the brute force's, each once;
 *      the invariants hold and the tree stays shallow.
 *   2. a random room of 300 objects flown 40 frames, objects deleted and
 *      made mid-run, and a pile under gravity with friction: the dumps of
 *      tree and sweep, heap on and off, are one set of bits; a run that
 *      switches the structure twice keeps them too. */
#include <stdlib.h>
#include <string.h>
#include "test.h"
#include "aabb_tree.h"
#include "scene.h"
#include "config.h"
#include "parallel/wire.h"
#include "parallel/wire.h"

#define TEST_LCG_SEED 2601ULL
#include "test_lcg.h"

#define NBOX 300

static vrAabb box[NBOX];
static int leaf[NBOX];                  /* -1: not in the tree */
static unsigned char seen[NBOX][NBOX];

/* a box of side 0.05..1 m in a 12 m cube, one in ten of 4 m; one in ten
 * put to touch box `touch` exactly (touching boxes overlap) */
static vrAabb random_box(int touch)
{
    vrAabb b;
    double s = uni() < 0.1 ? 4 : 0.05 + 0.95 * uni();
    b.lo = rvec(6);
    if (touch >= 0 && uni() < 0.1) b.lo.x = box[touch].hi.x;
    b.hi = vec3_add(b.lo, vec3_make(s * (0.2 + uni()), s * (0.2 + uni()), s * (0.2 + uni())));
    return b;
}

static void see_pair(void *ctx, int a, int b)
{
    (void)ctx;
    seen[a < b ? a : b][a < b ? b : a]++;
}

static void see_one(void *ctx, int a)
{
    (void)ctx;
    seen[0][a]++;
}

/* the pairs the tree met (seen) are the overlapping ones of the boxes
 * `in` says, each once: in(a, b) says whether a pair is one to meet */
static int pairs_are_exact(int (*in)(int a, int b), int *npairs)
{
    int a, b;
    *npairs = 0;
    for (a = 0; a < NBOX; a++)
        for (b = a + 1; b < NBOX; b++) {
            int want = in(a, b) && !vrAabb_Disjoint(&box[a], &box[b]);
            ENSURE_MSG(seen[a][b] == want, "boxes %d and %d: met %d times, overlap %d", a, b, seen[a][b], want);
            *npairs += want;
        }
    return 0;
}

static int both_in(int a, int b) { return leaf[a] >= 0 && leaf[b] >= 0; }
/* the cross test's two trees: the even ids in one, the odd in the other */
static int across(int a, int b) { return (a + b) % 2 == 1; }

static int tree_height(const vrTree *t) { return t->root < 0 ? 0 : t->node[t->root].height; }

/* one round of changes: a fifth of the slots toggled in or out, a fifth
 * refitted in place; on some rounds every leaf moved and refitted at once,
 * or the tree rebuilt */
static int change_round(vrTree *t, int round)
{
    int k, id;
    for (k = 0; k < NBOX / 5; k++) {
        id = (int)(uni() * NBOX);
        if (leaf[id] >= 0) {
            vrTree_Remove(t, leaf[id]);
            leaf[id] = -1;
        } else {
            box[id] = random_box((int)(uni() * NBOX));
            ENSURE((leaf[id] = vrTree_Insert(t, &box[id], id)) >= 0);
        }
    }
    for (k = 0; k < NBOX / 5; k++)
        if (leaf[id = (int)(uni() * NBOX)] >= 0) {
            box[id].lo = vec3_add(box[id].lo, rvec(0.5));
            box[id].hi = vec3_add(box[id].hi, rvec(0.2));
            box[id].hi = vec3_max(box[id].hi, box[id].lo);
            vrTree_Refit(t, leaf[id], &box[id]);
        }
    if (round % 4 == 1) {
        for (id = 0; id < NBOX; id++)
            if (leaf[id] >= 0) {
                box[id] = random_box(-1);
                vrTree_SetLeaf(t, leaf[id], &box[id]);
            }
        vrTree_RefitAll(t);
    }
    if (round % 7 == 3) ENSURE(vrTree_Rebuild(t) == 0);
    return 0;
}

static int test_tree_pairs_and_queries_equal_brute_force_through_changes(void)
{
    vrTree t;
    int round, id, k, npairs = 0, total = 0, maxh = 0;
    vrTree_Init(&t);
    for (id = 0; id < NBOX; id++) leaf[id] = -1;
    for (round = 0; round < 40; round++) {
        ENSURE(change_round(&t, round) == 0);
        ENSURE_MSG(vrTree_Check(&t, 1) == 0, "round %d: invariants broken", round);
        maxh = tree_height(&t) > maxh ? tree_height(&t) : maxh;
        memset(seen, 0, sizeof seen);
        vrTree_SelfPairs(&t, see_pair, NULL);
        if (pairs_are_exact(both_in, &npairs)) return 1;
        total += npairs;
        for (k = 0; k < 20; k++) {
            vrAabb q = random_box(-1);
            memset(seen[0], 0, sizeof seen[0]);
            vrTree_Query(&t, &q, see_one, NULL);
            for (id = 0; id < NBOX; id++)
                ENSURE(seen[0][id] == (leaf[id] >= 0 && !vrAabb_Disjoint(&q, &box[id])));
        }
    }
    printf("    %d overlapping pairs in 40 rounds of %d leaves at most; height %d at most\n", total, NBOX, maxh);
    ENSURE(total > 1000);               /* the boxes did meet */
    ENSURE(maxh <= 14);                 /* AVL: 1.44 log2(300) = 11.9 */
    vrTree_Free(&t);
    return 0;
}

static int test_pairs_across_two_trees_equal_brute_force(void)
{
    vrTree t[2];
    int id, npairs;
    vrTree_Init(&t[0]);
    vrTree_Init(&t[1]);
    for (id = 0; id < NBOX; id++) {
        box[id] = random_box(id > 0 ? id - 1 : -1);
        ENSURE(vrTree_Insert(&t[id % 2], &box[id], id) >= 0);
    }
    ENSURE(vrTree_Rebuild(&t[1]) == 0 && vrTree_Check(&t[1], 1) == 0);   /* one rebuilt, one as inserted */
    memset(seen, 0, sizeof seen);
    vrTree_CrossPairs(&t[0], &t[1], see_pair, NULL);
    if (pairs_are_exact(across, &npairs)) return 1;
    printf("    %d pairs across\n", npairs);
    ENSURE(npairs > 40);
    vrTree_Free(&t[0]);
    vrTree_Free(&t[1]);
    return 0;
}

/* ---- whole runs: tree and sweep, heap on and off ---------------------------------- */

static void use_tree(vrSettings *s) { s->broadphase = VR_BROADPHASE_TREE; }
static void use_sweep(vrSettings *s) { s->broadphase = VR_BROADPHASE_SWEEP; }

/* the four runs' settings: sweep and tree, heap on and off */
static void four_ways(vrWorld **w)
{
    vrScene_Set(w[0], use_sweep);
    vrScene_Set(w[2], use_sweep);
    vrScene_Set(w[1], use_tree);
    vrScene_Set(w[2], vrScene_HeapOff);
    vrScene_Set(w[3], vrScene_HeapOff);
    vrScene_Set(w[3], use_tree);
}

/* n random objects in a room of side `side` (time step h, d = 0.01, no
 * clamp taking energy out), gravity g, the friction and elasticity given */
static vrWorld *room(int n, double side, double h, double g, double mu, double e)
{
    vrSettings s = vrSettings_Default();
    s.room = side, s.seed = 26, s.collision_dist = 0.01, s.time_step = h;
    s.max_linear = 1000, s.max_angular = 10000;
    s.force_mag = g, s.default_friction = mu, s.default_elasticity = e;
    return vrScene_RandomRoom(&s, n);
}

/* the same room four times, set the four ways; -1 when one is refused */
static int four_rooms(vrWorld **w, int n, double side, double h, double g, double mu, double e)
{
    int i, made = 0;
    for (i = 0; i < 4; i++) made += (w[i] = room(n, side, h, g, mu, e)) != NULL;
    if (made < 4) {
        for (i = 0; i < 4; i++) vrWorld_Destroy(w[i]);
        return -1;
    }
    four_ways(w);
    return 0;
}

/* every ninth random object from `first` deleted, a ball flying where the
 * first `born` of them were (vrScene_ReplaceSome) */
static int replace_some(vrWorld *w, int n, int first, int born, const char *tag)
{
    return vrScene_ReplaceSome(w, n, first, 9, born, tag, vec3_make(1, -1, 2));
}

static int test_room_with_edits_same_bits_tree_and_sweep_heap_on_and_off(void)
{
    vrWorld *w[4];
    vrStats st;
    int i;
    ENSURE(four_rooms(w, 300, 10, 0.05, 0, 0, 1) == 0);
    ENSURE(vrScene_StepRuns(w, 4, 12) == 0);
    for (i = 0; i < 4; i++) ENSURE(replace_some(w[i], 300, 0, 12, "a") == 0);
    ENSURE(vrScene_StepRuns(w, 4, 14) == 0);
    for (i = 0; i < 4; i++) ENSURE(replace_some(w[i], 300, 4, 20, "b") == 0);
    ENSURE(vrScene_StepRuns(w, 4, 14) == 0);
    st = vrScene_Stats(w[0]);
    printf("    %d objects, %lld collisions in 40 frames\n", st.objects, st.collisions);
    ENSURE(st.collisions > 100);
    ENSURE(vrScene_SameRunsFreed(w, 4));
    return 0;
}

static int test_pile_same_bits_tree_and_sweep_heap_on_and_off(void)
{
    vrWorld *w[4];
    vrStats st;
    ENSURE(four_rooms(w, 100, 4, 0.01, 9.8, 0.5, 0.5) == 0);
    ENSURE(vrScene_StepRuns(w, 4, 250) == 0);
    st = vrScene_Stats(w[0]);
    printf("    pile: %lld collisions, %lld island contacts in 250 frames, %d resting\n", st.collisions,
           st.island_contacts, st.resting);
    ENSURE(st.collisions > 100 && st.island_contacts > 100);   /* a pile, not a fall */
    ENSURE(vrScene_SameRunsFreed(w, 4));
    return 0;
}

/* switching the structure mid-run remakes the owners and keeps the bits */
static int test_switching_structure_mid_run_keeps_the_bits(void)
{
    vrWorld *w[2];
    w[0] = room(200, 8, 0.05, 0, 0, 1), w[1] = room(200, 8, 0.05, 0, 0, 1);
    vrScene_Set(w[0], use_sweep);
    vrScene_Set(w[1], use_sweep);
    ENSURE(vrScene_StepRuns(w, 2, 10) == 0);
    vrScene_Set(w[1], use_tree);
    ENSURE(vrScene_StepRuns(w, 2, 10) == 0);
    vrScene_Set(w[1], use_sweep);
    ENSURE(vrScene_StepRuns(w, 2, 5) == 0);
    ENSURE(vrScene_Stats(w[0]).collisions > 20);
    ENSURE(vrScene_SameRunsFreed(w, 2));
    return 0;
}

/* the workers get the structure with the settings (params.tree on the
 * wire) and each makes its own pairs from it: with either structure, in the
 * process's workers or serially, the same bits through edits */
static void two_workers(vrSettings *s)
{
    s->gps = 2;
    snprintf(s->lcm_url, sizeof s->lcm_url, "memq://");
}

static void three_workers(vrSettings *s)
{
    two_workers(s);
    s->gps = 3;
    s->heap = 1;
    s->distribution = VR_DIST_IMPROVED;
}

/* ...which it reaches: the params message carries both choices both ways */
static int test_the_structure_and_the_heap_reach_the_workers(void)
{
    int tree, heap;
    for (tree = 0; tree < 2; tree++)
        for (heap = 0; heap < 2; heap++) {
            vrSettings s = vrSettings_Default();
            vrParams p, q;
            vroc_params_t m;
            s.broadphase = tree ? VR_BROADPHASE_TREE : VR_BROADPHASE_SWEEP;
            s.heap = heap;
            p = vrSettings_Params(&s);
            ENSURE(p.use_tree == tree && p.use_heap == heap);
            memset(&m, 0, sizeof m);
            memset(&q, 0, sizeof q);
            vrWire_PutParams(&m, &p);
            ENSURE(vrWire_GetParams(&m, &q) == 0);
            ENSURE_MSG(q.use_tree == tree && q.use_heap == heap, "tree %d heap %d: got %d %d", tree, heap, q.use_tree, q.use_heap);
        }
    return 0;
}

static int test_workers_give_the_serial_bits_with_either_structure(void)
{
    vrWorld *w[4];
    vrStats st;
    int i;
    ENSURE(four_rooms(w, 300, 10, 0.05, 0, 0, 1) == 0);
    vrScene_Set(w[2], two_workers);      /* sweep, heap off */
    vrScene_Set(w[3], three_workers);    /* tree, heap on */
    ENSURE(vrScene_StepRuns(w, 4, 10) == 0);
    for (i = 0; i < 4; i++) ENSURE(replace_some(w[i], 300, 2, 10, "c") == 0);
    ENSURE(vrScene_StepRuns(w, 4, 12) == 0);
    st = vrScene_Stats(w[3]);
    printf("    %d objects, %lld collisions in 22 frames, %d workers\n", st.objects, st.collisions, st.gps);
    ENSURE(st.gps == 3 && vrScene_Stats(w[2]).gps == 2);
    ENSURE(st.collisions > 50);
    ENSURE(vrScene_SameRunsFreed(w, 4));
    return 0;
}

static const vrTest tests[] = {
    TEST(test_tree_pairs_and_queries_equal_brute_force_through_changes),
    TEST(test_pairs_across_two_trees_equal_brute_force),
    TEST(test_room_with_edits_same_bits_tree_and_sweep_heap_on_and_off),
    TEST(test_pile_same_bits_tree_and_sweep_heap_on_and_off),
    TEST(test_switching_structure_mid_run_keeps_the_bits),
    TEST(test_the_structure_and_the_heap_reach_the_workers),
    TEST(test_workers_give_the_serial_bits_with_either_structure),
};

const vrTestSuite vrSuite_AabbTree = {"aabb_tree", tests, TEST_COUNT(tests), NULL, NULL, 0};
