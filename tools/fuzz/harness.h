/* harness.h — the driver every AFL++ harness here shares (SPEC 11).
 *
 * Built by afl-clang-fast, a harness runs in AFL++'s persistent mode: one
 * process takes many inputs from shared memory, each given to the
 * harness's fuzz_one(), which must leave nothing behind for the next.
 * Built by a plain compiler, the same file reads one input from the file
 * named on the command line (or stdin) and runs it once: that is how a
 * crash AFL++ found is replayed under the debugger or the sanitizers.
 * Include this once, from the harness's only .c file.
 */
#ifndef VROC_FUZZ_HARNESS_H
#define VROC_FUZZ_HARNESS_H

#include <stdio.h>
#include <stdlib.h>

/* the harness: one input, of len bytes (a NUL follows them) */
static void fuzz_one(const unsigned char *data, size_t len);

#define FUZZ_MAX_INPUT (1 << 20)   /* larger inputs are cut: AFL++ keeps them far smaller */

#ifdef __AFL_FUZZ_TESTCASE_LEN
#include <unistd.h>   /* read(), in AFL++'s macros */
__AFL_FUZZ_INIT();

int main(void)
{
    static unsigned char copy[FUZZ_MAX_INPUT + 1];
    unsigned char *buf;
    __AFL_INIT();
    buf = __AFL_FUZZ_TESTCASE_BUF;
    /* 10000 inputs a process: a slow leak or a global left dirty cannot pile up for long */
    while (__AFL_LOOP(10000)) {
        size_t len = (size_t)__AFL_FUZZ_TESTCASE_LEN;
        if (len > FUZZ_MAX_INPUT) len = FUZZ_MAX_INPUT;
        /* a copy with its NUL: AFL's buffer has no room promised past len */
        for (size_t i = 0; i < len; i++) copy[i] = buf[i];
        copy[len] = 0;
        fuzz_one(copy, len);
    }
    return 0;
}
#else
int main(int argc, char **argv)
{
    static unsigned char buf[FUZZ_MAX_INPUT + 1];
    FILE *f = argc > 1 ? fopen(argv[1], "rb") : stdin;
    size_t len;
    if (!f) {
        perror(argv[1]);
        return 2;
    }
    len = fread(buf, 1, FUZZ_MAX_INPUT, f);
    if (f != stdin) fclose(f);
    buf[len] = 0;
    fuzz_one(buf, len);
    return 0;
}
#endif

#endif
