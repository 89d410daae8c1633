/* shell_run.h — how the benchmarks that time the shell run it
 * (bench_contact.c, bench_scenes.c, bench_broadphase.c): the release
 * shell "$VROC_BUILD/vroc -q -b" (build/rel by default) on a script's
 * text, pinned to one core (taskset -c $VROC_BENCH_CPU, 0 by default, when
 * taskset exists), its `stats` lines read into one struct by field name
 * and every other line handed to the caller (a dump's bodies).  Each
 * bench is one program of its own (the Makefile), so this is a header. */
#ifndef VROC_BENCH_SHELL_RUN_H
#define VROC_BENCH_SHELL_RUN_H

#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

/* the fields of a `stats` line the benches read (0 when absent) */
typedef struct BenchStats {
    double frames, objects, dynamic, resting, pairs, subframes, subframes_thesis;
    double checks, heap_pops, collisions, island_contacts, clamps, live_pairs;
    double energy, sim_ms, render_ms;
} BenchStats;

/* the shell to run: its path and the pinning prefix ("" when unpinned) */
typedef struct BenchShell { char vroc[512], pin[64]; } BenchShell;

/* what a run hands back: each stats line parsed, each other line as read */
typedef struct BenchLines {
    void (*stats)(void *ctx, const BenchStats *s);
    void (*line)(void *ctx, const char *line);   /* may be NULL */
    void *ctx;
} BenchLines;

/* a `stats` line ("frames=... sim_ms=...") into s, field by field */
static inline void bench_parse_stats(const char *line, BenchStats *s)
{
    static const struct { const char *key; size_t off; } keys[] = {
        {"frames", offsetof(BenchStats, frames)}, {"objects", offsetof(BenchStats, objects)},
        {"dynamic", offsetof(BenchStats, dynamic)}, {"resting", offsetof(BenchStats, resting)},
        {"pairs", offsetof(BenchStats, pairs)}, {"subframes", offsetof(BenchStats, subframes)},
        {"subframes_thesis", offsetof(BenchStats, subframes_thesis)}, {"checks", offsetof(BenchStats, checks)},
        {"heap_pops", offsetof(BenchStats, heap_pops)}, {"collisions", offsetof(BenchStats, collisions)},
        {"island_contacts", offsetof(BenchStats, island_contacts)}, {"clamps", offsetof(BenchStats, clamps)},
        {"live_pairs", offsetof(BenchStats, live_pairs)}, {"energy", offsetof(BenchStats, energy)},
        {"sim_ms", offsetof(BenchStats, sim_ms)}, {"render_ms", offsetof(BenchStats, render_ms)}};
    char buf[4096], *save = NULL, *tok;
    size_t i;
    memset(s, 0, sizeof *s);
    snprintf(buf, sizeof buf, "%s", line);
    for (tok = strtok_r(buf, " \n", &save); tok; tok = strtok_r(NULL, " \n", &save)) {
        char *eq = strchr(tok, '=');
        if (!eq) continue;
        *eq = '\0';
        for (i = 0; i < sizeof keys / sizeof keys[0]; i++)
            if (!strcmp(tok, keys[i].key)) *(double *)((char *)s + keys[i].off) = strtod(eq + 1, NULL);
    }
}

/* the shell of $VROC_BUILD, pinned when taskset exists; -1 (said, as
 * `bench`) when there is none to run */
static inline int bench_shell_open(BenchShell *sh, const char *bench)
{
    const char *build = getenv("VROC_BUILD"), *cpu = getenv("VROC_BENCH_CPU");
    snprintf(sh->vroc, sizeof sh->vroc, "%s/vroc", build && *build ? build : "build/rel");
    sh->pin[0] = '\0';
    if (access(sh->vroc, X_OK)) {
        fprintf(stderr, "%s: no %s (make vroc; run from the repository root)\n", bench, sh->vroc);
        return -1;
    }
    if (system("command -v taskset >/dev/null 2>&1") == 0)
        snprintf(sh->pin, sizeof sh->pin, "taskset -c %s ", cpu && *cpu ? cpu : "0");
    return 0;
}

/* how the runs are pinned, for the machine line */
static inline const char *bench_shell_pinning(const BenchShell *sh)
{
    return sh->pin[0] ? sh->pin : "unpinned (no taskset)";
}

/* runs the script text through the shell (stdin from a temporary file, so
 * that its output can be read through popen); 1 when it exits 0 */
static inline int bench_shell_run(const BenchShell *sh, const char *text, const BenchLines *out)
{
    char path[] = "/tmp/vroc-bench-XXXXXX", cmd[1200], line[4096];
    int fd = mkstemp(path), ok = 0;
    FILE *f, *p;
    if (fd < 0) return 0;
    if (!(f = fdopen(fd, "w"))) {
        close(fd);
        unlink(path);
        return 0;
    }
    fputs(text, f);
    fclose(f);
    snprintf(cmd, sizeof cmd, "%s'%s' -q -b <'%s'", sh->pin, sh->vroc, path);
    if ((p = popen(cmd, "r"))) {
        while (fgets(line, sizeof line, p)) {
            if (!strncmp(line, "frames=", 7)) {
                BenchStats s;
                bench_parse_stats(line, &s);
                out->stats(out->ctx, &s);
            } else if (out->line) {
                out->line(out->ctx, line);
            }
        }
        ok = pclose(p) == 0;
    }
    unlink(path);
    return ok;
}

#endif
