/* peak_mem.h — a process's peak resident memory, for the tests and the
 * benchmarks that report one (tests/test_scale.c, bench/bench_scale.c):
 * its VmHWM from /proc.  Not getrusage's ru_maxrss: Linux carries a
 * process's peak across fork and exec, so a child of a big process (the
 * test runner is a gigabyte under ASan) reports its parent's.  Header
 * only, as netns.h, so that bench/ shares it without a rule of its own. */
#ifndef VROC_PEAK_MEM_H
#define VROC_PEAK_MEM_H

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/types.h>

/* the peak resident set (kB) of process pid (0: this one); -1 when /proc
 * cannot tell */
static long vrPeakMem_Kb(pid_t pid)
{
    char path[64], line[256];
    long kb = -1;
    FILE *f;
    if (pid) snprintf(path, sizeof path, "/proc/%ld/status", (long)pid);
    else snprintf(path, sizeof path, "/proc/self/status");
    if (!(f = fopen(path, "r"))) return -1;
    while (fgets(line, sizeof line, f))
        if (strncmp(line, "VmHWM:", 6) == 0) kb = strtol(line + 6, NULL, 10);
    fclose(f);
    return kb;
}

#endif
