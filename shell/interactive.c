/* interactive.c — the prompt: GNU readline's callback interface under a
 * pselect() loop, so that a real-time `start` runs one frame each
 * time_step of wall time while the user keeps typing (SPEC 1.2).  History
 * lives in ~/.vroc_history; TAB completes command and attribute names,
 * object names after object commands, show and delete, and file names
 * after read, file = and frames =. */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/select.h>
#include <time.h>
#include <unistd.h>
#include <readline/history.h>
#include <readline/readline.h>
#include "commands.h"

#define PROMPT "vroc> "
#define HISTORY_FILE ".vroc_history"
#define HISTORY_MAX 1000

static Shell *the_shell;   /* readline's callbacks carry no user pointer */
static int at_eof;
static int handler_on;      /* readline's line handler is installed */
/* SIGINT is blocked except while waiting for input (pselect) and while a
 * line runs: a Ctrl-C is then never lost between a check and the wait */
static sigset_t interrupt_open, interrupt_blocked;
static char history_path[VR_PATH_MAX];

/* ---- completion ------------------------------------------------------------- */

static const char **cands;   /* what the generator offers: ncands names */
static int ncands;

static char *generate(const char *text, int state)
{
    static int i;
    size_t len = strlen(text);
    if (!state) i = 0;
    while (i < ncands) {
        const char *c = cands[i++];
        if (strncmp(c, text, len) == 0) return strdup(c);
    }
    return NULL;
}

static char **offer(const char *text, const char **list, int n)
{
    cands = list;
    ncands = n;
    return rl_completion_matches(text, generate);
}

static char **offer_objects(const char *text)
{
    static const char **names;
    static vrObjectId *ids;
    vrWorld *w = the_shell->world;
    int n = vrWorld_ObjectCount(w), i;
    free(names);
    free(ids);
    names = malloc((size_t)(n + 1) * sizeof *names);
    ids = malloc((size_t)(n + 1) * sizeof *ids);
    if (!names || !ids) return NULL;
    vrWorld_ObjectList(w, ids, n);
    for (i = 0; i < n; i++) names[i] = vrWorld_ObjectName(w, ids[i]);
    return offer(text, names, n);
}

/* the complete words before the one being completed (the first one is
 * the command) and whether an '=' came among them */
static const Command *context(int start, int *words, int *assigned)
{
    const char *p = rl_line_buffer, *e = rl_line_buffer + start;
    const Command *c = NULL;
    *words = 0;
    *assigned = 0;
    while (p < e) {
        const char *w;
        while (p < e && (*p == ' ' || *p == '\t')) p++;
        if (p < e && *p == '=') {
            *assigned = 1;
            p++;
            continue;
        }
        for (w = p; p < e && *p != ' ' && *p != '\t' && *p != '='; p++)
            ;
        if (p > w && (*words)++ == 0) c = sh_find_command(w, (size_t)(p - w));
    }
    return c;
}

static char **complete(const char *text, int start, int end)
{
    int words, assigned;
    const Command *c = context(start, &words, &assigned);
    (void)end;
    rl_attempted_completion_over = 1;   /* no file names unless said below */
    if (words == 0) return offer(text, (const char **)sh_command_names(), sh_ncommands);
    if (!c) return NULL;
    if (words == 1 && c->form == F_NAME) return offer_objects(text);
    if (words == 1 && c->form == F_TOPIC) return offer(text, (const char **)sh_command_names(), sh_ncommands);
    if (c->form == F_PATH || (assigned && c->kind == K_TEXT)) {
        rl_attempted_completion_over = 0;   /* readline's file name completion */
        return NULL;
    }
    if (assigned && c->kind == K_CHOICE) {
        int n = 0;
        while (c->choices[n]) n++;
        return offer(text, (const char **)c->choices, n);
    }
    return NULL;
}

/* ---- history ---------------------------------------------------------------- */

static void history_open(void)
{
    const char *home = getenv("HOME");
    history_path[0] = '\0';
    if (!home || !home[0]) return;
    snprintf(history_path, sizeof history_path, "%s/%s", home, HISTORY_FILE);
    stifle_history(HISTORY_MAX);
    if (read_history(history_path) != 0) write_history(history_path);   /* create it */
}

/* each line goes to the file at once: a killed session keeps its history.
 * Blanks around it (a completion's trailing space) are not kept. */
static void history_add(const char *line)
{
    HIST_ENTRY *last = history_length > 0 ? history_get(history_base + history_length - 1) : NULL;
    size_t len;
    char *copy;
    while (*line == ' ' || *line == '\t') line++;
    for (len = strlen(line); len > 0 && (line[len - 1] == ' ' || line[len - 1] == '\t'); len--)
        ;
    if (len == 0 || (last && strncmp(last->line, line, len) == 0 && last->line[len] == '\0')) return;
    copy = strndup(line, len);
    if (!copy) return;
    add_history(copy);
    free(copy);
    if (history_path[0]) append_history(1, history_path);
}

static void history_close(void)
{
    if (history_path[0]) history_truncate_file(history_path, HISTORY_MAX);
}

/* ---- the loop --------------------------------------------------------------- */

/* The handler goes from inside the last line's callback: left installed,
 * readline would show the prompt once more after Ctrl-D or quit. */
static void remove_handler(void)
{
    if (handler_on) rl_callback_handler_remove();
    handler_on = 0;
}

static void on_line(char *line)
{
    Shell *sh = the_shell;
    if (!line) {
        at_eof = 1;
        remove_handler();
        putchar('\n');
        return;
    }
    history_add(line);
    sh->src->line++;
    sh->bailing = 0;   /* -b stops scripts; the prompt goes on */
    sh_interrupted = 0;
    sigprocmask(SIG_SETMASK, &interrupt_open, NULL);   /* Ctrl-C stops a long step */
    sh_exec_line(sh, line, strlen(line));
    sigprocmask(SIG_SETMASK, &interrupt_blocked, NULL);
    sh_interrupted = 0;   /* it belonged to that line */
    free(line);
    if (sh->quit) remove_handler();
    fflush(stdout);
}

/* an error of a real-time frame arrives while the prompt waits: print it
 * above the prompt and the text being typed */
static void tick(Shell *sh)
{
    char err[SH_ERR_MAX];
    char *typed;
    int point;
    if (sh_tick(sh, err, sizeof err) == 0) return;
    typed = rl_copy_text(0, rl_end);
    point = rl_point;
    rl_save_prompt();
    rl_replace_line("", 0);
    rl_redisplay();
    putchar('\r');
    sh_error_at(sh, sh->run_origin, err);
    rl_restore_prompt();
    rl_replace_line(typed ? typed : "", 0);
    rl_point = point;
    rl_forced_update_display();
    free(typed);
}

static void on_interrupt(int sig)
{
    (void)sig;
    sh_interrupted = 1;
}

/* Ctrl-C at the prompt stops a real-time `start`, as it stops a long
 * `step`, and drops the line being typed, as a shell does */
static void drop_line(Shell *sh)
{
    if (sh->running) {
        sh->running = 0;
        fflush(stdout);
        fprintf(stderr, "\nvroc: %s: note: start stopped by Ctrl-C", sh->run_origin);
    }
    sh_interrupted = 0;
    rl_free_line_state();
    rl_callback_sigcleanup();
    rl_replace_line("", 0);
    rl_crlf();
    rl_on_new_line();
    rl_redisplay();
}

static void install_signals(void)
{
    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_interrupt;   /* no SA_RESTART: pselect() returns at once */
    sigemptyset(&sa.sa_mask);
    sigaction(SIGINT, &sa, NULL);
    rl_catch_signals = 0;
    sigprocmask(SIG_SETMASK, NULL, &interrupt_open);
    sigdelset(&interrupt_open, SIGINT);
    interrupt_blocked = interrupt_open;
    sigaddset(&interrupt_blocked, SIGINT);
    sigprocmask(SIG_SETMASK, &interrupt_blocked, NULL);
}

static int wait_input(Shell *sh)
{
    fd_set fds;
    struct timespec ts, *tsp = NULL;
    double wait = sh_frame_wait(sh), win = sh_window_wait(sh);
    if (win >= 0 && (wait < 0 || win < wait)) wait = win;   /* the window's input too */
    if (wait >= 0) {
        ts.tv_sec = (time_t)wait;
        ts.tv_nsec = (long)((wait - (double)ts.tv_sec) * 1e9);
        tsp = &ts;
    }
    FD_ZERO(&fds);
    FD_SET(STDIN_FILENO, &fds);
    return pselect(STDIN_FILENO + 1, &fds, NULL, NULL, tsp, &interrupt_open);
}

int sh_interactive(Shell *sh)
{
    Source src;
    sh_source_init(&src, "<stdin>", "");
    /* cppcheck-suppress autoVariables ; set back to NULL before this returns */
    sh->src = &src;
    the_shell = sh;
    printf("VROC %s, Virtual and Real Object Collisions (Aliaga 1993); type help for the commands\n", VROC_VERSION);
    fflush(stdout);
    rl_readline_name = "vroc";
    rl_attempted_completion_function = complete;
    install_signals();
    history_open();
    rl_callback_handler_install(PROMPT, on_line);
    handler_on = 1;
    while (!at_eof && !sh->quit) {
        int r = wait_input(sh);
        if (r < 0 && errno == EINTR) {
            if (sh_interrupted) drop_line(sh);
            continue;
        }
        if (r < 0) break;
        sh_window_service(sh);
        if (r == 0 && sh_frame_wait(sh) == 0) tick(sh);
        else rl_callback_read_char();
    }
    remove_handler();
    sigprocmask(SIG_SETMASK, &interrupt_open, NULL);
    history_close();
    sh->src = NULL;
    return 0;
}
