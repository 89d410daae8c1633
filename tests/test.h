/* test.h — the tiny test harness (Box2D's test_macros.h is the model).
 *
 * A test is `static int test_name(void)` returning 0 when it passes; ENSURE*
 * print the failing line and return 1.  Each tests/test_*.c ends with a
 * table of its tests, `const vrTestSuite vrSuite_Name`, that tests/main.c
 * lists once; main.c is the one runner (build/VARIANT/tests/vroc-tests):
 * it runs the tests its arguments select, counts them, and ends with the
 * line `N passed, M failed` that tests/run.sh adds up.
 */
#ifndef VROC_TEST_H
#define VROC_TEST_H

#include <math.h>
#include <stdio.h>
#include <string.h>

#define ENSURE(cond)                                                                  \
    do {                                                                              \
        if (!(cond)) {                                                                \
            printf("    %s:%d: ENSURE(%s) failed\n", __FILE__, __LINE__, #cond);      \
            return 1;                                                                 \
        }                                                                             \
    } while (0)

#define ENSURE_MSG(cond, ...)                                                         \
    do {                                                                              \
        if (!(cond)) {                                                                \
            printf("    %s:%d: ENSURE(%s) failed: ", __FILE__, __LINE__, #cond);      \
            printf(__VA_ARGS__);                                                      \
            printf("\n");                                                             \
            return 1;                                                                 \
        }                                                                             \
    } while (0)

/* |a - b| <= tol, printing both values when not */
#define ENSURE_NEAR(a, b, tol)                                                        \
    do {                                                                              \
        double ea_ = (a), eb_ = (b), et_ = (tol);                                     \
        if (!(fabs(ea_ - eb_) <= et_)) {                                              \
            printf("    %s:%d: ENSURE_NEAR(%s, %s, %s) failed: %.17g vs %.17g "       \
                   "(diff %.3g)\n", __FILE__, __LINE__, #a, #b, #tol, ea_, eb_,      \
                   fabs(ea_ - eb_));                                                  \
            return 1;                                                                 \
        }                                                                             \
    } while (0)

typedef int (*vrTestFn)(void);

/* one test: its name (what a filter matches) and its function */
typedef struct vrTest {
    const char *name;
    vrTestFn run;
} vrTest;

/* a table entry: TEST(test_name) */
#define TEST(fn) { #fn, fn }

/* the tests of one file, in the order they run */
typedef struct vrTestSuite {
    const char *name;          /* the file's name without test_ and .c */
    const vrTest *tests;
    int count;
    int (*setup)(void);        /* NULL, or run before its first selected test: nonzero fails the suite */
    void (*teardown)(void);    /* NULL, or run after its last selected test */
    int netns;                 /* needs UDP multicast: the runner enters a private network namespace */
} vrTestSuite;

#define TEST_COUNT(table) ((int)(sizeof(table) / sizeof((table)[0])))

/* runs one test now (main.c counts it): prints `ok   NAME` or `FAIL NAME` */
void vrTest_Run(const char *name, vrTestFn fn);
#define RUN_TEST(fn) vrTest_Run(#fn, fn)

#endif
