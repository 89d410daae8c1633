/* bench_parallel.c — the thesis's table 5.5 on this machine: frames per
 * second with 1, 2, 4 and 8 worker processes over UDP multicast, messages
 * and wall time per frame, objects and pairs per worker; the thesis scenes
 * (through ./vroc) and random 20..100; and the LCM round trip between two
 * processes.  Runs in a private network namespace (tests/netns.h).
 *
 * SPEC 10's heavy frames (issue 26): `rooms` — N objects in a room of
 * SPEC 10's density without gravity, serial, gps = 1 and 2 interleaved
 * over udpm, each run in a fresh child, the median of RUNS: frames/s,
 * rounds a frame by kind, messages a frame, the SGP's waiting and the
 * workers' busy time a frame.  `bench_parallel rooms [N [FRAMES [RUNS]]]`
 * runs that table alone.  `heavy` — 64 superquadrics of RES x RES points
 * (heavy looks, few events), the same columns: `bench_parallel heavy [RES
 * [FRAMES [RUNS]]]` alone.
 *
 * This machine has 2 cores: more workers than cores only adds messages.
 * The figures say how the protocol costs, not how Pixel-Planes 5 scaled. */
#define _DEFAULT_SOURCE
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>
#include <math.h>
#include <lcm/lcm.h>
#include "vroc.h"
#include "../tests/netns.h"
#include "in_child.h"

#define UDPM "udpm://239.255.76.67:7667?ttl=0&recv_buf_size=4194304"
static const int workers[] = {0, 1, 2, 4, 8};
#define NW 5

typedef struct { double fps, msgs, ms; long long copies_min, copies_max, pairs_min, pairs_max; int ok; } vrRow;

static void span(const long long *v, int n, long long *lo, long long *hi)
{
    int i;
    *lo = *hi = n > 0 ? v[0] : 0;
    for (i = 1; i < n; i++) {
        if (v[i] < *lo) *lo = v[i];
        if (v[i] > *hi) *hi = v[i];
    }
}

static vrRow from_stats(const vrStats *s, int ok)
{
    vrRow r;
    memset(&r, 0, sizeof r);
    r.ok = ok && s->frames > 0;
    r.fps = s->sim_ms > 0 ? 1000.0 * (double)s->frames / s->sim_ms : 0;
    r.msgs = s->frames ? (double)s->messages / (double)s->frames : 0;
    r.ms = s->frames ? s->sim_ms / (double)s->frames : 0;
    span(s->gp_copies, s->gps, &r.copies_min, &r.copies_max);
    span(s->gp_pairs, s->gps, &r.pairs_min, &r.pairs_max);
    return r;
}

static vrRow random_run(int n, int gps, long frames)
{
    vrWorld *w = vrWorld_Create();
    vrSettings s = *vrWorld_Settings(w);
    vrStats st;
    int ok;
    s.room = 6;
    s.seed = 20 + (unsigned)n;
    s.collision_dist = 0.01;
    s.time_step = 0.05;
    s.force_mag = 9.8;
    s.max_linear = 16;
    s.max_angular = 20;
    s.gps = gps;
    snprintf(s.lcm_url, sizeof s.lcm_url, "%s", UDPM);
    vrWorld_SetSettings(w, &s, NULL, 0);
    vrWorld_AddRandom(w, n, NULL, 0);
    ok = vrWorld_Step(w, frames, NULL, 0) == 0;
    vrWorld_GetStats(w, &st);
    vrWorld_Destroy(w);
    return from_stats(&st, ok);
}

/* a scene through the shell: read it, step, and parse the stats line */
static long long key(const char *line, const char *k)
{
    const char *p = strstr(line, k);
    return p ? atoll(p + strlen(k)) : 0;
}

static double keyd(const char *line, const char *k)
{
    const char *p = strstr(line, k);
    return p ? atof(p + strlen(k)) : 0;
}

static void keylist(const char *line, const char *k, long long *v, int n)
{
    const char *p = strstr(line, k);
    int i;
    for (i = 0; i < n; i++) {
        v[i] = p ? atoll(p += (i ? 1 : (int)strlen(k))) : 0;
        if (p) p += strspn(p, "0123456789");
    }
}

static vrRow scene_run(const char *vroc, const char *scene, int gps, long frames)
{
    char cmd[1024], line[8192] = "";
    vrStats st;
    FILE *f;
    int ok;
    snprintf(cmd, sizeof cmd,
             "printf 'lcm_url = %s\\ngps = %d\\nmax_frames = 0\\nread %s\\nstep %ld\\nstats\\n' | %s -q 2>/dev/null | tail -n 1",
             UDPM, gps, scene, frames, vroc);
    memset(&st, 0, sizeof st);
    f = popen(cmd, "r");
    ok = f && fgets(line, sizeof line, f) != NULL;
    if (f) pclose(f);
    st.frames = key(line, "frames=");
    st.sim_ms = keyd(line, "sim_ms=");
    st.messages = key(line, "messages=");
    st.gps = gps;
    keylist(line, "gp_copies=", st.gp_copies, gps);
    keylist(line, "gp_pairs=", st.gp_pairs, gps);
    return from_stats(&st, ok);
}

static void print_row(const char *name, int gps, vrRow r)
{
    if (!r.ok) {
        printf("%-22s %4d  (failed)\n", name, gps);
        return;
    }
    printf("%-22s %4d %9.0f %9.1f %9.2f   %5lld-%-5lld %6lld-%-6lld\n", name, gps, r.fps, r.msgs, r.ms,
           r.copies_min, r.copies_max, r.pairs_min, r.pairs_max);
    printf("csv,parallel,%s,%d,%.1f,%.2f,%.3f,%lld,%lld,%lld,%lld\n", name, gps, r.fps, r.msgs, r.ms,
           r.copies_min, r.copies_max, r.pairs_min, r.pairs_max);
}

/* ping-pong between two processes over udpm: the median round trip */
static void on_ping(const lcm_recv_buf_t *rb, const char *ch, void *user)
{
    (void)ch;
    lcm_publish(user, "PONG", rb->data, rb->data_size);
}

static int got;
static void on_pong(const lcm_recv_buf_t *rb, const char *ch, void *user)
{
    (void)rb;
    (void)ch;
    (void)user;
    got = 1;
}

static double now_us(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec * 1e6 + (double)t.tv_nsec * 1e-3;
}

static int cmpd(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

static void round_trip(void)
{
    enum { N = 1000 };
    static double rtt[N];
    pid_t pid = fork();
    lcm_t *l;
    int i, k = 0, status;
    if (pid == 0) {
        lcm_t *e = lcm_create(UDPM);
        if (!e) _exit(1);
        lcm_subscribe(e, "PING", on_ping, e);
        for (;;) lcm_handle(e);
    }
    l = lcm_create(UDPM);
    if (!l) {
        printf("LCM round trip: cannot open %s\n", UDPM);
        kill(pid, SIGKILL);
        waitpid(pid, &status, 0);
        return;
    }
    lcm_subscribe(l, "PONG", on_pong, NULL);
    for (i = 0; i < N + 50; i++) {
        double t0 = now_us();
        got = 0;
        lcm_publish(l, "PING", "x", 1);
        while (!got && now_us() - t0 < 100000) lcm_handle_timeout(l, 100);
        if (got && i >= 50) rtt[k++] = now_us() - t0;   /* the first 50 warm up */
    }
    qsort(rtt, (size_t)k, sizeof rtt[0], cmpd);
    printf("LCM round trip between two processes over udpm: median %.0f us, 90th percentile %.0f us (%d of %d)\n",
           k ? rtt[k / 2] : 0, k ? rtt[k * 9 / 10] : 0, k, N);
    printf("csv,lcm_round_trip_us,%.1f,%.1f\n", k ? rtt[k / 2] : 0, k ? rtt[k * 9 / 10] : 0);
    lcm_destroy(l);
    kill(pid, SIGKILL);
    waitpid(pid, &status, 0);
}

/* ---- SPEC 10's heavy frames --------------------------------------------------------- */

typedef struct Room {
    int ok;
    double frames, sim_ms, wait_ms, busy_ms, rounds[5];
    long long messages, collisions;
} Room;

/* A heavy room: 64 superquadrics of res x res points (exponents 0.6,
 * radii 0.3 to 0.4 m) on a 4 x 4 x 4 lattice in a 10 m room of six static
 * walls, flying at up to 3 m/s and turning at up to 2 rad/s, no gravity,
 * e = 1.  Each look at a pair walks and bounds hulls of res^2 vertices. */
static int heavy_room(vrWorld *w, int res, char *err, size_t n)
{
    static const double wall[6][6] = {{5.5, 5.5, 0.25, 0, 0, -0.25}, {5.5, 5.5, 0.25, 0, 0, 10.25},
                                      {0.25, 5.5, 5.5, -5.25, 0, 5}, {0.25, 5.5, 5.5, 5.25, 0, 5},
                                      {5.5, 0.25, 5.5, 0, -5.25, 5}, {5.5, 0.25, 5.5, 0, 5.25, 5}};
    unsigned long long seed = 7;
    int k;
    for (k = 0; k < 6 + 64; k++) {
        vrObjectDef d = vrObjectDef_Default(k < 6 ? VR_CUBE : VR_SUPERQUADRIC);
        vrObjectId id;
        char name[16];
        int j, q = k - 6;
        snprintf(name, sizeof name, k < 6 ? "wall%d" : "q%d", k < 6 ? k : q);
        d.elasticity = 1;
        if (k < 6) {
            for (j = 0; j < 3; j++) d.size[j] = wall[k][j], d.translate[j] = wall[k][3 + j];
            d.mass = -1, d.mass_set = 1;
        } else {
            d.ures = d.vres = res;
            d.exp1 = d.exp2 = 0.6;
            d.a1 = 0.4, d.a2 = 0.3, d.a3 = 0.35;
            d.mass = 1, d.mass_set = 1;
            d.translate[0] = -3.6 + 2.4 * (q / 16), d.translate[1] = -3.6 + 2.4 * (q / 4 % 4);
            d.translate[2] = 1.5 + 2.4 * (q % 4);
            for (j = 0; j < 3; j++) {
                seed = seed * 6364136223846793005ULL + 1442695040888963407ULL;
                d.linear_vel[j] = 6.0 * (double)(seed >> 11) / 9007199254740992.0 - 3;
                seed = seed * 6364136223846793005ULL + 1442695040888963407ULL;
                d.angular_vel[j] = 4.0 * (double)(seed >> 11) / 9007199254740992.0 - 2;
            }
        }
        if (vrWorld_CreateObject(w, name, d.type, &id, err, n) != 0 || vrWorld_SetObjectDef(w, id, &d, err, n) != 0)
            return -1;
    }
    return 0;
}

/* in this (child) process: the room built and started (the workers set
 * up), one frame to warm, then frames frames counted; res > 0: the heavy
 * room of superquadrics of res x res points instead of n random objects */
static Room room_run(int n, int res, int gps, long frames)
{
    vrWorld *w = vrWorld_Create();
    vrSettings s = *vrWorld_Settings(w);
    vrStats a, b;
    Room r;
    char err[256] = "";
    int i, failed;
    memset(&r, 0, sizeof r);
    s.room = res > 0 ? 0 : 22.1 * cbrt(n / 500.0);   /* SPEC 10's density: 10,000 in 60 m */
    s.seed = 1993;
    s.collision_dist = 0.01;
    s.time_step = res > 0 ? 0.1 : 0.05;
    s.max_linear = 1000;
    s.max_angular = 10000;
    s.gps = gps;
    snprintf(s.lcm_url, sizeof s.lcm_url, "%s", UDPM);
    failed = vrWorld_SetSettings(w, &s, err, sizeof err) != 0;
    if (!failed) failed = res > 0 ? heavy_room(w, res, err, sizeof err) != 0 : vrWorld_AddRandom(w, n, err, sizeof err) != 0;
    if (failed || vrWorld_Step(w, 1, err, sizeof err) != 0) {
        fprintf(stderr, "bench_parallel: room of %d, gps %d: %s\n", n, gps, err);
        vrWorld_Destroy(w);
        return r;
    }
    vrWorld_GetStats(w, &a);
    r.ok = vrWorld_Step(w, frames, err, sizeof err) == 0;
    if (!r.ok) fprintf(stderr, "bench_parallel: room of %d, gps %d: %s\n", n, gps, err);
    vrWorld_GetStats(w, &b);
    r.frames = (double)(b.frames - a.frames);
    r.sim_ms = b.sim_ms - a.sim_ms;
    r.wait_ms = b.wait_ms - a.wait_ms;
    r.busy_ms = b.gp_busy_ms - a.gp_busy_ms;
    for (i = 0; i < 5; i++) r.rounds[i] = (double)(b.rounds[i] - a.rounds[i]);
    r.messages = b.messages - a.messages;
    r.collisions = b.collisions - a.collisions;
    vrWorld_Destroy(w);
    return r;
}

typedef struct RoomArgs { int n, res, gps; long frames; } RoomArgs;

static void room_child(const void *ctx, void *out)
{
    const RoomArgs *a = ctx;
    *(Room *)out = room_run(a->n, a->res, a->gps, a->frames);
}

static Room room_in_child(int n, int res, int gps, long frames)
{
    RoomArgs a = {n, res, gps, frames};
    Room r;
    bench_in_child(room_child, &a, &r, sizeof r);
    return r;
}

static double room_fps(const Room *r) { return r->sim_ms > 0 ? 1000.0 * r->frames / r->sim_ms : 0; }

static int by_room_fps(const void *x, const void *y)
{
    double a = room_fps(x), b = room_fps(y);
    return a < b ? -1 : a > b;
}

/* ahead = 0: "2t", the thesis's rounds */
static void print_room(int n, int gps, int ahead, const Room *m, double serial_fps)
{
    double f = m->frames > 0 ? m->frames : 1, rounds = 0;
    int i;
    for (i = 0; i < 5; i++) rounds += m->rounds[i];
    printf("%6d %4d%s %9.1f %6.2f %8.1f %6.1f %6.1f %6.1f %6.1f %8.1f %8.2f %8.2f %8.2f\n", n, gps, ahead ? " " : "t", room_fps(m),
           serial_fps > 0 ? room_fps(m) / serial_fps : 0, rounds / f, m->rounds[0] / f, m->rounds[1] / f,
           m->rounds[2] / f, m->rounds[3] / f, (double)m->messages / f, m->sim_ms / f, m->wait_ms / f,
           m->busy_ms / f);
    printf("csv,rooms,%d,%d%s,%.2f,%.3f,%.2f,%.2f,%.2f,%.2f,%.2f,%.1f,%.3f,%.3f,%.3f,%.2f\n", n, gps, ahead ? "" : "t", room_fps(m),
           serial_fps > 0 ? room_fps(m) / serial_fps : 0, rounds / f, m->rounds[0] / f, m->rounds[1] / f,
           m->rounds[2] / f, m->rounds[3] / f, (double)m->messages / f, m->sim_ms / f, m->wait_ms / f,
           m->busy_ms / f, (double)m->collisions / f);
}

#define ROOM_RUNS_MAX 15

/* serial, gps = 1 and 2, and gps = 2 with the thesis's rounds (an advance
 * per event, a round at every island step: VROC_THESIS_ROUNDS=1),
 * interleaved (the machine's load shifts), medians */
static void rooms_table(int n, long frames, int runs)
{
    static const int gps[] = {0, 1, 2, 2}, ahead[] = {1, 1, 1, 0};
    Room r[4][ROOM_RUNS_MAX];
    int i, g;
    if (runs > ROOM_RUNS_MAX) runs = ROOM_RUNS_MAX;
    for (i = 0; i < runs; i++)
        for (g = 0; g < 4; g++) {
            if (ahead[g]) unsetenv("VROC_THESIS_ROUNDS");
            else setenv("VROC_THESIS_ROUNDS", "1", 1);
            r[g][i] = room_in_child(n, 0, gps[g], frames);
        }
    unsetenv("VROC_THESIS_ROUNDS");
    for (g = 0; g < 4; g++) qsort(r[g], (size_t)runs, sizeof r[g][0], by_room_fps);
    for (g = 0; g < 4; g++) {
        const Room *m = &r[g][runs / 2];
        if (!m->ok) {
            printf("%6d %4d%s  (failed)\n", n, gps[g], ahead[g] ? " " : "t");
            continue;
        }
        print_room(n, gps[g], ahead[g], m, room_fps(&r[0][runs / 2]));
    }
}

static void columns(void)
{
    printf("rounds a frame: all, frame starts, events, advances, island steps; ms a frame: the frame, the SGP's\n"
           "waits, the workers' work (summed); 2t: gps = 2 with the thesis's rounds (VROC_THESIS_ROUNDS=1)\n");
    printf("%6s %4s %9s %6s %8s %6s %6s %6s %6s %8s %8s %8s %8s\n", "objs", "gps", "frames/s", "vs 0", "rounds",
           "start", "event", "adv", "island", "msgs", "ms", "wait", "busy");
}

/* the heavy room: serial, gps = 1 and 2, interleaved, medians */
static void heavy_table(int res, long frames, int runs)
{
    static const int gps[] = {0, 1, 2};
    Room r[3][ROOM_RUNS_MAX];
    int i, g;
    if (runs > ROOM_RUNS_MAX) runs = ROOM_RUNS_MAX;
    printf("\nheavy frames: 64 superquadrics of %d x %d points flying in a 10 m room, no gravity, %ld frames of\n"
           "0.1 s (24 contact steps each) after one, over udpm, median of %d interleaved runs\n",
           res, res, frames, runs);
    columns();
    for (i = 0; i < runs; i++)
        for (g = 0; g < 3; g++) r[g][i] = room_in_child(64, res, gps[g], frames);
    for (g = 0; g < 3; g++) qsort(r[g], (size_t)runs, sizeof r[g][0], by_room_fps);
    for (g = 0; g < 3; g++) {
        const Room *m = &r[g][runs / 2];
        if (!m->ok) printf("%6d %4d   (failed)\n", 64, gps[g]);
        else print_room(64, gps[g], 1, m, room_fps(&r[0][runs / 2]));
    }
}

static void rooms_header(long frames, int runs)
{
    printf("\nSPEC 10 rooms over udpm, no gravity, %ld frames of 0.05 s after one, median of %d interleaved runs\n",
           frames, runs);
    columns();
}

int main(int argc, char **argv)
{
    static const char *const scenes[] = {"simple", "desks", "basketball", "office", "bounce"};
    const char *build = getenv("VROC_BUILD") ? getenv("VROC_BUILD") : "build/rel";
    char vroc[512];
    int i, g, n;
    enter_namespace(argc, argv);
    setvbuf(stdout, NULL, _IOLBF, 0);
    if (argc > 1 && strcmp(argv[1], "rooms") == 0) {
        long frames = argc > 3 ? atol(argv[3]) : 20;
        int runs = argc > 4 ? atoi(argv[4]) : 5;
        rooms_header(frames, runs);
        rooms_table(argc > 2 ? atoi(argv[2]) : 1000, frames, runs);
        return 0;
    }
    if (argc > 1 && strcmp(argv[1], "heavy") == 0) {
        heavy_table(argc > 2 ? atoi(argv[2]) : 150, argc > 3 ? atol(argv[3]) : 10, argc > 4 ? atoi(argv[4]) : 3);
        return 0;
    }
    snprintf(vroc, sizeof vroc, "%s/vroc", build);
    round_trip();
    printf("\nworkers over udpm on %ld cores (0 = serial); fps from sim_ms; objects and pairs per worker (min-max)\n",
           sysconf(_SC_NPROCESSORS_ONLN));
    printf("%-22s %4s %9s %9s %9s   %11s %13s\n", "scene", "gps", "fps", "msgs/fr", "ms/fr", "objects/gp", "pairs/gp");
    for (i = 0; i < 5; i++) {
        char path[256], name[64];
        snprintf(path, sizeof path, "scenes/%s.cmd", scenes[i]);
        if (access(path, R_OK) != 0) {
            printf("%-22s  (no %s)\n", scenes[i], path);
            continue;
        }
        snprintf(name, sizeof name, "%s", scenes[i]);
        for (g = 0; g < NW; g++) print_row(name, workers[g], scene_run(vroc, path, workers[g], 100));
    }
    for (n = 20; n <= 100; n += 20) {
        char name[64];
        snprintf(name, sizeof name, "random %d (%d pairs)", n, n * (n - 1) / 2);
        for (g = 0; g < NW; g++) print_row(name, workers[g], random_run(n, workers[g], 60));
    }
    rooms_header(20, 5);
    for (n = 500; n <= 1000; n += 500) rooms_table(n, 20, 5);
    heavy_table(150, 10, 3);
    return 0;
}
