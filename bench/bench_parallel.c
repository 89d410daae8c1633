/* bench_parallel.c — the thesis's table 5.5 on this machine: frames per
 * second with 1, 2, 4 and 8 worker processes over UDP multicast, messages
 * and wall time per frame, objects and pairs per worker; the thesis scenes
 * (through ./vroc) and random 20..100; and the LCM round trip between two
 * processes.  Runs in a private network namespace (tests/netns.h).
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
#include <lcm/lcm.h>
#include "vroc.h"
#include "../tests/netns.h"

#define UDPM "udpm://239.255.76.67:7667?ttl=0"
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

int main(int argc, char **argv)
{
    static const char *const scenes[] = {"simple", "desks", "basketball", "office", "bounce"};
    const char *build = getenv("VROC_BUILD") ? getenv("VROC_BUILD") : "build/rel";
    char vroc[512];
    int i, g, n;
    enter_namespace(argc, argv);
    setvbuf(stdout, NULL, _IOLBF, 0);
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
    return 0;
}
