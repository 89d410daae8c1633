/* in_child.h — a measurement in a fresh child process (make bench), so
 * that its peak memory and its heap are its own: the child runs fn(ctx,
 * out) and sends out's size bytes back through a pipe.  Shared by the
 * benchmarks that fork a run per figure (bench_scale.c, bench_parallel.c). */
#ifndef VROC_BENCH_IN_CHILD_H
#define VROC_BENCH_IN_CHILD_H

#include <stdio.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

/* 0, or -1 with out zeroed (no pipe, no child, or a child that died) */
static int bench_in_child(void (*fn)(const void *ctx, void *out), const void *ctx, void *out, size_t size)
{
    int fd[2], ok;
    pid_t pid;
    memset(out, 0, size);
    fflush(stdout);
    if (pipe(fd) != 0) return -1;
    if ((pid = fork()) == 0) {
        fn(ctx, out);
        close(fd[0]);
        _exit(write(fd[1], out, size) == (ssize_t)size ? 0 : 2);
    }
    close(fd[1]);
    ok = pid > 0 && read(fd[0], out, size) == (ssize_t)size;
    close(fd[0]);
    if (pid > 0) waitpid(pid, NULL, 0);
    if (!ok) memset(out, 0, size);
    return ok ? 0 : -1;
}

#endif
