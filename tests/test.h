/* test.h — the tiny test harness (Box2D's test_macros.h is the model).
 *
 * A test is `static int test_name(void)` returning 0 when it passes; ENSURE*
 * print the failing line and return 1.  main() calls test_init(argc, argv),
 * then RUN_TEST for each test (argv[1], when given, is a substring filter on
 * test names), then returns test_summary(), which prints the line
 * `N passed, M failed` that tests/run.sh adds up.
 */
#ifndef VROC_TEST_H
#define VROC_TEST_H

#include <math.h>
#include <stdio.h>
#include <string.h>

static int test_passed_, test_failed_;
static const char *test_filter_;

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

#define RUN_TEST(fn)                                                                  \
    do {                                                                              \
        if (!test_filter_ || strstr(#fn, test_filter_)) {                             \
            int r_ = fn();                                                            \
            printf("%s %s\n", r_ == 0 ? "ok  " : "FAIL", #fn);                        \
            fflush(stdout);                                                           \
            if (r_ == 0) test_passed_++; else test_failed_++;                         \
        }                                                                             \
    } while (0)

static inline void test_init(int argc, char **argv)
{
    test_filter_ = argc > 1 ? argv[1] : NULL;
    setvbuf(stdout, NULL, _IOLBF, 0);
}

static inline int test_summary(void)
{
    printf("%d passed, %d failed\n", test_passed_, test_failed_);
    return test_failed_ != 0;
}

#endif
