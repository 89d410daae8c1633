/* fuzz_shell.c — AFL++ harness for the command parser (SPEC 11): an input
 * is a script, run line by line through sh_exec_line in a fresh session,
 * as `vroc -q` would run it, so that parsing, range checks and the
 * handlers behind them all meet the fuzzer's lines.
 *
 * Two things keep an input a test of vroc rather than of the machine:
 *   - statements that reach outside the process are skipped (read: any
 *     file on the disk; display, refresh, frames: OSMesa and files; gps,
 *     lcm_url: worker processes and the network) — they are one-line
 *     parsers of a path, a word or an integer, covered by the goldens;
 *   - a budget of CPU time per input: when it runs out, a long `step` or
 *     `start` is interrupted as SIGINT interrupts it, and the rest of the
 *     input is skipped.  A script as long as asked is fine (SPEC 11); a
 *     frame that never ends is not, and it still shows as a hang.
 */
#include <signal.h>
#include <string.h>
#include <sys/time.h>
#include "shell.h"
#include "harness.h"

#define BUDGET_MS 25

static volatile sig_atomic_t over;

static void on_budget(int sig)
{
    (void)sig;
    over = 1;
    sh_interrupted = 1;
}

static void arm(long ms)
{
    struct itimerval it;
    memset(&it, 0, sizeof it);
    it.it_value.tv_sec = ms / 1000;
    it.it_value.tv_usec = (ms % 1000) * 1000;
    setitimer(ITIMER_VIRTUAL, &it, NULL);
}

/* the first word of a line, past blanks */
static int skipped(const char *line, size_t len)
{
    static const char *const outside[] = {"read", "display", "refresh", "frames", "gps", "lcm_url"};
    size_t i = 0, w, k;
    while (i < len && (line[i] == ' ' || line[i] == '\t')) i++;
    for (w = i; w < len && line[w] != ' ' && line[w] != '\t' && line[w] != '=' && line[w] != '\n'; w++) continue;
    for (k = 0; k < sizeof outside / sizeof outside[0]; k++)
        if (w - i == strlen(outside[k]) && strncmp(line + i, outside[k], w - i) == 0) return 1;
    return 0;
}

static void run_lines(Shell *sh, char *text, size_t len)
{
    char *p = text, *end = text + len;
    while (p < end && !sh->quit && !over) {
        char *nl = memchr(p, '\n', (size_t)(end - p));
        size_t n = nl ? (size_t)(nl - p) + 1 : (size_t)(end - p);
        char save = p[n];
        sh->src->line++;
        p[n] = '\0';   /* sh_exec_line sees one line with its NUL, as getline gives it */
        if (!skipped(p, n)) sh_exec_line(sh, p, n);
        p[n] = save;
        p += n;
    }
}

static void fuzz_one(const unsigned char *data, size_t len)
{
    static char text[FUZZ_MAX_INPUT + 1];
    Shell sh;
    Source src;
    memset(&sh, 0, sizeof sh);
    sh.world = vrWorld_Create();
    if (!sh.world) return;
    sh.view = vrView_Default();
    sh.selected = VR_NO_OBJECT;
    sh.quiet = 1;
    sh_source_init(&src, "fuzz.cmd", "");
    sh.src = &src;
    memcpy(text, data, len + 1);
    over = 0;
    sh_interrupted = 0;
    signal(SIGVTALRM, on_budget);
    arm(BUDGET_MS);
    run_lines(&sh, text, len);
    arm(0);
    sh_display_close(&sh);
    vrWorld_Destroy(sh.world);
}
