/* test_scale.c — SPEC 10: 10,000 objects.  A pair's record exists only
 * while its bodies' boxes meet (src/pair_life.c), so the memory a room of
 * flying objects takes grows with the objects, not with the n(n-1)/2 pairs
 * (50 M for 10,000: gigabytes if each had a record); and the runs keep
 * their bits: heap on and off agree with objects created and deleted
 * mid-run at 10,000 objects, and the serial run agrees with workers, whose
 * owners are lazy too, each making records only of the pairs the deal
 * gives it (src/parallel/distribution.c, a function of the two ids): with
 * 1, 2 and 3 workers, both distributions, through edits and a worker
 * dying.  Workers' memory follows the objects too.  Frames per second
 * and peak memory are bench/bench_scale.c's. */
#define _DEFAULT_SOURCE
#include <stdlib.h>
#include <string.h>
#include <stdio.h>
#include <sys/wait.h>
#include <unistd.h>
#include "test.h"
#include "vroc.h"
#include "scene.h"
#include "peak_mem.h"
#include "event.h"
#include "grow.h"
#include "contact_set.h"
#include "rest.h"
#include "shape_share.h"

#define BIG 10000

/* SPEC 10's room: N objects flying in a room of side s without gravity, no
 * clamp taking energy out */
static vrWorld *flying_room(int n, double side, int heap)
{
    vrSettings s = vrSettings_Default();
    s.room = side;
    s.seed = 10000;
    s.collision_dist = 0.01;
    s.time_step = 0.05;
    s.max_linear = 1000;
    s.max_angular = 10000;
    s.heap = heap;
    return vrScene_RandomRoom(&s, n);
}

/* mid-run edits (vrScene_ReplaceSome): balls named late0.. */
static int replace_some(vrWorld *w, int n, int first, int stride, int born)
{
    return vrScene_ReplaceSome(w, n, first, stride, born, "late", vec3_make(0, 1, -1));
}

static int edit_mid_run(vrWorld *w) { return replace_some(w, BIG, 0, 97, 40); }

static int run_edited(vrWorld *w, unsigned long long *hash, vrStats *st)
{
    if (!w || vrScene_Step(w, 2) != 0 || edit_mid_run(w) != 0 || vrScene_Step(w, 2) != 0) return -1;
    *hash = vrScene_DumpHash(w);
    *st = vrScene_Stats(w);
    return 0;
}

static int test_heap_on_and_off_agree_at_10000_objects_with_edits(void)
{
    vrWorld *a = flying_room(BIG, 60, 1), *b = flying_room(BIG, 60, 0);
    unsigned long long ha = 0, hb = 1;
    vrStats sa, sb;
    int ra = run_edited(a, &ha, &sa), rb = run_edited(b, &hb, &sb);
    vrWorld_Destroy(a);
    vrWorld_Destroy(b);
    ENSURE(ra == 0 && rb == 0);
    printf("    %d objects, %lld collisions, %lld live pairs of %ld\n", sa.objects, sa.collisions, sa.live_pairs,
           sa.pairs);
    ENSURE(sa.objects == 6 + BIG - (BIG + 96) / 97 + 40);
    ENSURE(sa.collisions > 0);            /* the runs did something to agree on */
    ENSURE_MSG(ha == hb, "dumps differ: heap on %llx, off %llx", ha, hb);
    ENSURE(sa.collisions == sb.collisions);
    /* the logical count stays n(n-1)/2 + the walls' pairs; the records are
     * the close few (a thousandth of a percent) */
    ENSURE(sa.pairs == (long)(sa.dynamic) * (sa.dynamic - 1) / 2 + 6L * sa.dynamic);
    ENSURE_MSG(sa.live_pairs > 0 && sa.live_pairs < 2 * sa.objects, "%lld live pairs", sa.live_pairs);
    return 0;
}

/* the peak resident memory (kB) of a fresh vroc ($VROC_BUILD/vroc, as
 * tests/run.sh sets it) that builds a room of n objects and flies it 3
 * frames, with gps workers in its own process (memq://): its VmHWM (peak_mem.h), read while it waits for more input
 * after the room's `stats`; -1 on failure (no vroc is a failure, not a
 * skip) */
static long room_kb(int n, double side, int gps)
{
    const char *build = getenv("VROC_BUILD");
    char vroc[512], line[4096];
    int in[2], out[2], status = 0, seen = 0;
    long kb = -1;
    FILE *to, *from;
    pid_t pid;
    if (!build || pipe(in) != 0) return -1;
    if (pipe(out) != 0) return close(in[0]), close(in[1]), -1;
    snprintf(vroc, sizeof vroc, "%s/vroc", build);
    if ((pid = fork()) == 0) {
        dup2(in[0], 0), dup2(out[1], 1);
        close(in[0]), close(in[1]), close(out[0]), close(out[1]);
        execl(vroc, vroc, "-q", "-b", (char *)NULL);
        _exit(3);
    }
    close(in[0]), close(out[1]);
    to = fdopen(in[1], "w"), from = fdopen(out[0], "r");
    if (pid > 0 && to && from) {
        fprintf(to, "seed = 10000\ncollision_dist = 0.01\ntime_step = 0.05\nmax_linear = 1000\nmax_angular = 10000\n"
                    "max_frames = 0\nroom = %.17g\nrandom %d\ngps = %d\nlcm_url = memq://\nstart\nstep 3\nstats\n",
                side, n, gps);
        fflush(to);
        while (!seen && fgets(line, sizeof line, from)) seen = strncmp(line, "frames=", 7) == 0;
        if (seen) kb = vrPeakMem_Kb(pid);
    }
    if (to) fclose(to);
    else close(in[1]);
    if (from) fclose(from);
    else close(out[0]);
    if (pid > 0 && waitpid(pid, &status, 0) != pid) return -1;
    return WIFEXITED(status) && WEXITSTATUS(status) == 0 ? kb : -1;
}

/* Four times the objects at the same density: sixteen times the pairs,
 * about four times the memory.  With a record per pair (some 100 bytes
 * each) 10,000 objects would take 5 GB and the step from 2,500 would cost
 * over 300 kB per added object; the measured cost per object is printed
 * (under ASan here, whose shadow and quarantine inflate it; bench_scale
 * reports the release build's) */
static int test_memory_grows_with_the_objects_not_the_pairs(void)
{
    long small = room_kb(BIG / 4, 60 / 1.5874, 0), big = room_kb(BIG, 60, 0);   /* 4^(1/3) = 1.5874 */
    double per_object;
    ENSURE_MSG(small > 0 && big > small, "%ld kB, %ld kB (VROC_BUILD=%s)", small, big,
               getenv("VROC_BUILD") ? getenv("VROC_BUILD") : "unset");
    per_object = (big - small) * 1024.0 / (BIG - BIG / 4);
    printf("    %ld kB for %d objects, %ld kB for %d: %.0f bytes per added object\n", small, BIG / 4, big, BIG,
           per_object);
    /* 5.5 kB here, 8.4 kB under ASan; 20 kB when each object had its own
     * hull and drawing mesh (shape_share.h) */
    ENSURE_MSG(per_object < 12e3, "%.0f bytes per object", per_object);
    ENSURE_MSG(big < 2L * 1024 * 1024, "%ld kB", big);
    return 0;
}

/* the first sphere of a random room, made finer (ures 12: a shape no
 * other object has) */
static vrObjectId finer_sphere(vrWorld *w, int n)
{
    int k;
    for (k = 0; k < n; k++) {
        char name[16];
        vrObjectDef d;
        vrObjectId id;
        snprintf(name, sizeof name, "r%d", k);
        id = vrWorld_FindObject(w, name);
        if (vrWorld_GetObjectDef(w, id, &d) != 0 || d.type != VR_SPHERE) continue;
        d.ures = 12;
        return vrWorld_SetObjectDef(w, id, &d, NULL, 0) == 0 ? id : VR_NO_OBJECT;
    }
    return VR_NO_OBJECT;
}

/* Objects of one shape share it (src/shape_share.c): a room of 2,000
 * random spheres and cubes (one size each) holds a sphere, a cube and its
 * walls' shapes, not 2,000 hulls (a default sphere's is 26 kB); a sphere
 * made finer gets a shape of its own while the others keep theirs; a
 * deleted object's reference goes, and the shapes go with the world.  The
 * bits are the same as with a hull each: every determinism test runs on
 * shared shapes, and the peers' rooms' dumps did not move. */
static int test_equal_shapes_are_built_once(void)
{
    int before = vrShape_Count(), room, edited;
    vrWorld *w = flying_room(2000, 35, 1);
    ENSURE(w && vrScene_Step(w, 1) == 0);
    room = vrShape_Count() - before;
    ENSURE(finer_sphere(w, 2000) != VR_NO_OBJECT);
    ENSURE(vrWorld_DeleteObject(w, vrWorld_FindObject(w, "r1")) == 0);
    ENSURE(vrScene_Step(w, 1) == 0);
    edited = vrShape_Count() - before;
    vrWorld_Destroy(w);
    printf("    2,000 objects and 6 walls: %d shapes; one sphere made finer: %d\n", room, edited);
    ENSURE_MSG(room >= 2 && room <= 5, "%d shapes", room);
    ENSURE(edited == room + 1);
    ENSURE(vrShape_Count() == before);
    return 0;
}

/* serial (lazy records) against workers (lazy records of the pairs dealt
 * to them) through deletions and additions; in one process (memq://) */
static unsigned long long hash_with(int gps, int n, vrStats *st)
{
    vrWorld *w = flying_room(n, 8, 1);
    vrSettings s;
    unsigned long long h = 0;
    if (!w) return 0;
    s = *vrWorld_Settings(w);
    s.gps = gps;
    snprintf(s.lcm_url, sizeof s.lcm_url, "memq://");
    vrWorld_SetSettings(w, &s, NULL, 0);
    if (vrScene_Step(w, 20) != 0 || replace_some(w, n, 1, 9, 10) != 0) goto done;
    if (vrScene_Step(w, 20) != 0) goto done;
    h = vrScene_DumpHash(w);
    *st = vrScene_Stats(w);
done:
    vrWorld_Destroy(w);
    return h;
}

static int test_serial_lazy_pairs_agree_with_workers_through_edits(void)
{
    vrStats s0, s2, s3;
    unsigned long long h0 = hash_with(0, 300, &s0), h2 = hash_with(2, 300, &s2), h3 = hash_with(3, 300, &s3);
    ENSURE(h0 != 0 && h2 != 0 && h3 != 0);
    printf("    %lld collisions; live pairs: serial %lld, 2 workers %lld\n", s0.collisions, s0.live_pairs,
           s2.live_pairs);
    ENSURE(s0.collisions > 50);
    ENSURE_MSG(h0 == h2 && h0 == h3, "serial %llx, 2 workers %llx, 3 workers %llx", h0, h2, h3);
    ENSURE(s0.live_pairs < s0.pairs / 10);
    return 0;
}

/* Two workers in the vroc process (memq://) at 10,000 objects: each is a
 * copy of the objects it needs (all of them, at two workers) and records
 * of its close pairs, so a worker costs about what the serial run does.
 * With a record of every pair dealt to it, as workers had, each held 25 M
 * (some 3 GB); at setup the SGP listed all 50 M. */
static int test_a_worker_costs_memory_of_its_objects_not_its_pairs(void)
{
    long serial = room_kb(BIG, 60, 0), two = room_kb(BIG, 60, 2);
    double per_gp = (two - serial) / 2.0;
    ENSURE_MSG(serial > 0 && two > serial, "%ld kB serially, %ld kB with 2 workers", serial, two);
    printf("    10,000 objects: %ld kB serially, %ld kB with 2 workers in the process: %.0f kB a worker\n", serial,
           two, per_gp);
    ENSURE_MSG(per_gp < 1.5 * serial, "%.0f kB a worker", per_gp);
    return 0;
}

/* a room with gps workers (memq://) of distribution dist, flown 3
 * frames, edited (every 37th object deleted, 20 balls born in their
 * places), flown 3 more; kill: VROC_FAULT_KILL for the run ("" none) */
static int run_workers(int n, double side, int heap, int gps, vrDistribution dist, const char *kill,
                       unsigned long long *hash, vrStats *st)
{
    vrWorld *w = flying_room(n, side, heap);
    vrSettings s;
    int r = -1;
    if (!w) return -1;
    s = *vrWorld_Settings(w);
    s.gps = gps;
    s.distribution = dist;
    snprintf(s.lcm_url, sizeof s.lcm_url, "memq://");
    if (kill[0]) setenv("VROC_FAULT_KILL", kill, 1);
    if (vrWorld_SetSettings(w, &s, NULL, 0) == 0 && vrScene_Step(w, 3) == 0 && replace_some(w, n, 5, 37, 20) == 0
        && vrScene_Step(w, 3) == 0) {
        *hash = vrScene_DumpHash(w);
        *st = vrScene_Stats(w);
        r = 0;
    }
    unsetenv("VROC_FAULT_KILL");
    vrWorld_Destroy(w);
    return r;
}

/* the workers' shares of the pairs (the deal's counts) add up to the
 * logical count: no pair without an owner, none with two */
static long long shares(const vrStats *st)
{
    long long sum = 0;
    int i;
    for (i = 0; i < st->gps && i < 64; i++) sum += st->gp_pairs[i];
    return sum;
}

#define MID 2000

/* 2,000 objects three times as dense as SPEC 10's room (25 m): serial,
 * heap off, 1 worker (round robin), 2 (improved), 3 (round robin) of which
 * worker 1 falls silent at the first frame after the edit (its pairs are
 * dealt to the two others, the frame redone): one dump */
static int test_lazy_workers_agree_with_serial_through_edits_and_a_death(void)
{
    static const struct { int heap, gps; vrDistribution dist; const char *kill, *what; } runs[] = {
        {0, 0, VR_DIST_ROUND_ROBIN, "", "heap off"},
        {1, 1, VR_DIST_ROUND_ROBIN, "", "1 worker"},
        {1, 2, VR_DIST_IMPROVED, "", "2 workers, improved"},
        {1, 3, VR_DIST_ROUND_ROBIN, "1:4", "3 workers, worker 1 dying"},
    };
    unsigned long long h0 = 0, h;
    vrStats s0, st;
    size_t k;
    ENSURE(run_workers(MID, 25, 1, 0, VR_DIST_ROUND_ROBIN, "", &h0, &s0) == 0);
    printf("    %d objects: %lld collisions, %lld records of %ld pairs serially\n", s0.objects, s0.collisions,
           s0.live_pairs, s0.pairs);
    ENSURE(s0.collisions > 20);
    ENSURE(s0.objects == 6 + MID - (MID - 5 + 36) / 37 + 20);
    for (k = 0; k < sizeof runs / sizeof runs[0]; k++) {
        ENSURE_MSG(run_workers(MID, 25, runs[k].heap, runs[k].gps, runs[k].dist, runs[k].kill, &h, &st) == 0, "%s",
                   runs[k].what);
        ENSURE_MSG(h == h0, "%s: dump %llx, serial %llx", runs[k].what, h, h0);
        ENSURE(st.collisions == s0.collisions);
        if (runs[k].gps == 0) continue;
        ENSURE_MSG(shares(&st) == st.pairs, "%s: shares %lld of %ld pairs", runs[k].what, shares(&st), st.pairs);
        /* the workers' records are the close pairs, as the serial owner's */
        ENSURE_MSG(st.live_pairs > 0 && st.live_pairs < 4 * s0.live_pairs + 100, "%s: %lld records", runs[k].what,
                   st.live_pairs);
        printf("    %s: %lld records\n", runs[k].what, st.live_pairs);
    }
    ENSURE_MSG(st.gp_copies[1] == 0 && st.gp_pairs[0] > 0 && st.gp_pairs[2] > 0, "worker 1 was to die");
    return 0;
}

/* ---- a world's update merged into the pending states ---------------------------- */

/* what vrUpdate_Merge must do, a state at a time: replace the first state
 * of the body, or add one */
static int merge_by_search(vrUpdate *to, const vrUpdate *from)
{
    int i, k;
    for (i = 0; i < from->n; i++) {
        for (k = 0; k < to->n && to->body[k].id != from->body[i].id; k++) continue;
        if (k == to->n && vrGrow((void **)&to->body, &to->cap, to->n + 1, sizeof *to->body) != 0) return -1;
        if (k == to->n) to->n++;
        to->body[k] = from->body[i];
    }
    return 0;
}

/* n states of ids drawn below nid (repeats included), each marked by its t */
static int random_states(vrUpdate *u, int n, int nid, unsigned *seed, double mark)
{
    int i;
    vrUpdate_Init(u);
    if (vrGrow((void **)&u->body, &u->cap, n + 1, sizeof *u->body) != 0) return -1;
    memset(u->body, 0, (size_t)(n + 1) * sizeof *u->body);
    for (i = 0; i < n; i++) {
        *seed = *seed * 1103515245u + 12345u;
        u->body[i].id = (int)((*seed >> 8) % (unsigned)nid);
        u->body[i].t = mark + i;
    }
    u->n = n;
    return 0;
}

/* a whole world's update (10,000 states into 10,000 pending) is merged by
 * a table of ids, not a search per state (quadratic: 200 M comparisons at
 * a 10,000-object start), with the search's result, repeats and all; and
 * a small update by the search itself */
/* bodies in an island's contact step (in contact and awake) missing from
 * the contact set, which island steps visit in place of every object
 * (contact_set.c); -1 when it cannot be pruned.  *in_contact: how many
 * are in contact and awake. */
static int set_misses(vrWorld *w, int *in_contact)
{
    int i, k = 0, missing = 0;
    if (vrContactSet_Prune(w) != 0) return -1;
    for (i = 0; i < w->table.n; i++) {
        const vrObject *o = w->table.obj[i];
        if (!o || !o->live || !o->body.contact || o->body.resting) continue;
        (*in_contact)++;
        while (k < w->ncontact_ids && w->contact_ids[k] < i) k++;
        missing += !(k < w->ncontact_ids && w->contact_ids[k] == i);
    }
    return missing;
}

/* A pile of 60 settling with friction, objects deleted and made at frame
 * 100, saved at 200 and read into a fresh world that goes on beside it:
 * after every frame each body in contact is in the set, and the two
 * worlds end with the same bits. */
static int test_the_contact_set_holds_every_body_in_contact_through_edits_and_a_save(void)
{
    vrSettings s = vrSettings_Default();
    vrWorld *w, *b = NULL;
    int f, seen = 0;
    s.room = 4, s.seed = 3, s.time_step = 0.01, s.collision_dist = 0.01, s.force_mag = 9.8;
    s.default_friction = 0.5, s.default_elasticity = 0.5;
    w = vrScene_RandomRoom(&s, 60);
    ENSURE(w != NULL);
    for (f = 1; f <= 300; f++) {
        int missing;
        ENSURE(vrScene_Step(w, 1) == 0);
        if (b) ENSURE(vrScene_Step(b, 1) == 0);
        missing = set_misses(w, &seen);
        ENSURE_MSG(missing == 0, "frame %d: %d bodies in contact not in the set", f, missing);
        if (b) ENSURE(set_misses(b, &seen) == 0);
        if (f == 100) ENSURE(vrScene_ReplaceSome(w, 60, 0, 7, 4, "late", vec3_make(0, 0, -1)) == 0);
        if (f == 200) {
            char *text = NULL;
            size_t len = 0;
            FILE *out = open_memstream(&text, &len);
            ENSURE(out && vrWorld_WriteSave(w, out, vrScene_DefLine, NULL) == 0);
            fclose(out);
            b = vrWorld_Create();
            ENSURE(vrScene_ReadSave(w, b, text) == 0);
            free(text);
        }
    }
    printf("    %d body-frames in contact, every one in the set\n", seen);
    ENSURE(seen > 5000);
    ENSURE(vrScene_SameDumps(w, b));
    vrWorld_Destroy(w);
    vrWorld_Destroy(b);
    return 0;
}

/* every object's frame pose taken now, as every frame end once did */
static void take_frame_poses(vrWorld *w)
{
    int i;
    for (i = 0; i < w->table.n; i++)
        if (w->table.obj[i]) vrRest_KeepFramePose(w, w->table.obj[i]);
}

/* Frame poses are taken lazily (rest.c): from a body's anchor when the
 * rest test or a save asks, or before an update moves the anchor.  A pile
 * of 60 settling with friction, frame by frame, beside one whose poses
 * are all taken at every frame end: the same bits at every frame, and
 * bodies come to rest in both. */
static int test_frame_poses_taken_lazily_rest_a_pile_as_taken_at_every_frame_end(void)
{
    vrSettings s = vrSettings_Default();
    vrWorld *lazy, *eager;
    int f;
    s.room = 4, s.seed = 5, s.time_step = 0.01, s.collision_dist = 0.01, s.force_mag = 9.8;
    s.default_friction = 0.5, s.default_elasticity = 0.5;
    lazy = vrScene_RandomRoom(&s, 60);
    eager = vrScene_RandomRoom(&s, 60);
    ENSURE(lazy && eager);
    for (f = 1; f <= 600; f++) {
        ENSURE(vrScene_Step(lazy, 1) == 0 && vrScene_Step(eager, 1) == 0);
        take_frame_poses(eager);
        ENSURE_MSG(vrScene_DumpHash(lazy) == vrScene_DumpHash(eager), "frame %d: the runs differ", f);
    }
    printf("    600 frames alike, %d of 60 at rest\n", vrScene_Stats(lazy).resting);
    ENSURE(vrScene_Stats(lazy).resting >= 30);
    vrWorld_Destroy(lazy);
    vrWorld_Destroy(eager);
    return 0;
}

static int test_a_world_update_merges_as_the_search_would(void)
{
    static const int sizes[][3] = {{10000, 10000, 12000}, {3, 5, 40}, {0, 16, 20}, {500, 16, 700}};
    unsigned seed = 26;
    size_t c;
    for (c = 0; c < sizeof sizes / sizeof sizes[0]; c++) {
        vrUpdate to, ref, from;
        int i, same;
        ENSURE(random_states(&to, sizes[c][0], sizes[c][2], &seed, 0) == 0);
        ENSURE(random_states(&from, sizes[c][1], sizes[c][2], &seed, 1e6) == 0);
        vrUpdate_Init(&ref);
        ENSURE(vrGrow((void **)&ref.body, &ref.cap, to.n + 1, sizeof *ref.body) == 0);
        if (to.n) memcpy(ref.body, to.body, (size_t)to.n * sizeof *ref.body);
        ref.n = to.n;
        ENSURE(merge_by_search(&ref, &from) == 0);
        ENSURE(vrUpdate_Merge(&to, &from, sizes[c][2]) == 0);
        same = to.n == ref.n;
        for (i = 0; same && i < to.n; i++) same = to.body[i].id == ref.body[i].id && to.body[i].t == ref.body[i].t;
        ENSURE_MSG(same, "case %zu: %d states merged, %d by the search", c, to.n, ref.n);
        ENSURE(c != 0 || to.n > 10000);     /* some added, some replaced */
        vrUpdate_Free(&to), vrUpdate_Free(&ref), vrUpdate_Free(&from);
    }
    return 0;
}

static const vrTest tests[] = {
    TEST(test_heap_on_and_off_agree_at_10000_objects_with_edits),
    TEST(test_memory_grows_with_the_objects_not_the_pairs),
    TEST(test_equal_shapes_are_built_once),
    TEST(test_serial_lazy_pairs_agree_with_workers_through_edits),
    TEST(test_a_worker_costs_memory_of_its_objects_not_its_pairs),
    TEST(test_lazy_workers_agree_with_serial_through_edits_and_a_death),
    TEST(test_a_world_update_merges_as_the_search_would),
    TEST(test_the_contact_set_holds_every_body_in_contact_through_edits_and_a_save),
    TEST(test_frame_poses_taken_lazily_rest_a_pile_as_taken_at_every_frame_end),
};

const vrTestSuite vrSuite_Scale = {"scale", tests, TEST_COUNT(tests), NULL, NULL, 0};
