/* main.c — the test runner: every suite of tests/test_*.c in one binary
 * (Box2D's test/main.c is the model).
 *
 *   vroc-tests [--list] [FILTER...]
 *
 * With no FILTER every test runs.  A FILTER that is a suite's name (its
 * file's, without test_ and .c: `impacts`, `heap`) selects that suite's
 * tests; any other selects the tests, in every suite, whose names contain
 * it.  Each test prints `ok   NAME` or `FAIL NAME` after the lines it
 * prints itself; the last line is `N passed, M failed` (tests/run.sh adds
 * it up), and the exit status is 1 when a test failed.  --list prints the
 * suites and the names of their selected tests instead of running them.
 *
 *   is_suite_name  — whether a filter names a suite (then it is not a substring)
 *   selected       — whether the filters pick a test of a suite
 *   any_selected   — whether they pick any of its tests
 *   needs_netns    — whether a selected test needs a private network namespace
 *   run_suite      — a suite's setup, its selected tests, its teardown
 *   list_suite     — the names --list prints
 */
#include <stdio.h>
#include <string.h>
#include "test.h"
#include "netns.h"

/* every suite, once.  The display's first: they need a process in which no
 * display was opened yet (no other suite opens one, and this keeps it so) */
#define VR_SUITES(X)                                                              \
    X(Render) X(Mass) X(Polyhedron) X(Motion) X(Closest) X(Contact) X(Support) X(FineHulls)    \
    X(Distbound) X(Broadphase) X(AabbTree) X(Reach) X(Schedule) X(Response) X(Island) X(Impacts) X(Instant) \
    X(Tunnelling) X(Rest) X(Sliding) X(Heap) X(Quiet) X(Energy) X(Clamps) X(Stacking) X(Scale) X(Track) X(Grab) X(Sound) X(Save) X(Parallel) X(ParallelSound) \
    X(Window) X(Hand) X(Wire) X(Panel)

#define VR_DECLARE(s) extern const vrTestSuite vrSuite_##s;
VR_SUITES(VR_DECLARE)
#define VR_ENTRY(s) &vrSuite_##s,
static const vrTestSuite *const suites[] = {VR_SUITES(VR_ENTRY)};

static int passed, failed;
static char **filters;
static int nfilters;

void vrTest_Run(const char *name, vrTestFn fn)
{
    int r = fn();
    printf("%s %s\n", r == 0 ? "ok  " : "FAIL", name);
    fflush(stdout);
    if (r == 0) passed++;
    else failed++;
}

static int is_suite_name(const char *f)
{
    size_t k;
    for (k = 0; k < sizeof suites / sizeof suites[0]; k++)
        if (strcmp(f, suites[k]->name) == 0) return 1;
    return 0;
}

/* a suite's name selects that suite; any other filter, the tests whose names contain it */
static int selected(const vrTestSuite *s, const vrTest *t)
{
    int i;
    if (nfilters == 0) return 1;
    for (i = 0; i < nfilters; i++) {
        if (is_suite_name(filters[i]) ? strcmp(filters[i], s->name) == 0 : strstr(t->name, filters[i]) != NULL)
            return 1;
    }
    return 0;
}

static int any_selected(const vrTestSuite *s)
{
    int i;
    for (i = 0; i < s->count; i++)
        if (selected(s, &s->tests[i])) return 1;
    return 0;
}

static int needs_netns(void)
{
    size_t k;
    for (k = 0; k < sizeof suites / sizeof suites[0]; k++)
        if (suites[k]->netns && any_selected(suites[k])) return 1;
    return 0;
}

static void run_suite(const vrTestSuite *s)
{
    int i;
    if (!any_selected(s)) return;
    if (s->setup && s->setup() != 0) {
        printf("FAIL %s: its setup failed\n", s->name);
        failed++;
        return;
    }
    for (i = 0; i < s->count; i++)
        if (selected(s, &s->tests[i])) vrTest_Run(s->tests[i].name, s->tests[i].run);
    if (s->teardown) s->teardown();
}

static void list_suite(const vrTestSuite *s)
{
    int i;
    if (!any_selected(s)) return;
    printf("%s\n", s->name);
    for (i = 0; i < s->count; i++)
        if (selected(s, &s->tests[i])) printf("    %s\n", s->tests[i].name);
}

int main(int argc, char **argv)
{
    int list = argc > 1 && strcmp(argv[1], "--list") == 0;
    size_t k, n = sizeof suites / sizeof suites[0];
    filters = argv + 1 + list;
    nfilters = argc - 1 - list;
    setvbuf(stdout, NULL, _IOLBF, 0);
    if (!list && needs_netns()) enter_namespace(argc, argv);
    for (k = 0; k < n; k++) (list ? list_suite : run_suite)(suites[k]);
    if (list) return 0;
    printf("%d passed, %d failed\n", passed, failed);
    return failed != 0;
}
