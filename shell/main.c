/* main.c — `vroc [options] [-e STATEMENT] [file...]`: options and modes
 * (SPEC 1).
 *
 * As in SQLite's shell and lua.c, isatty(0) decides: a terminal and no
 * inputs gives the banner and the prompt; otherwise statements are read
 * as a script, silently.  The inputs on the command line (files, `-e
 * STATEMENT`, `-` for the standard input, as lua.c takes them) are read
 * in order, then vroc exits, or with -i goes on at the prompt.  Exit
 * status: 0 when every statement succeeded, 1 after any error, 2 for bad
 * usage.
 */
#include <stdio.h>
#include <sys/stat.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "shell.h"

/* one input named on the command line, in its order */
typedef enum InputKind { IN_FILE, IN_STATEMENT, IN_STDIN } InputKind;
typedef struct Input {
    InputKind kind;
    const char *arg;
} Input;

typedef struct Options {
    int bail, quiet, stay, ninputs;
    Input *inputs;   /* argc entries: no input takes more than one word */
} Options;

static void usage(FILE *f)
{
    fprintf(f, "usage: vroc [-b] [-q] [-i] [-e STATEMENT] [file | -]...\n"
               "Virtual and Real Object Collisions: reads commands from the files, or\n"
               "from the standard input (a prompt when it is a terminal).\n"
               "  -b            stop at the first error (bail)\n"
               "  -q            quiet: do not print notes\n"
               "  -i            after the inputs, stay at the prompt\n"
               "  -e STATEMENT  run STATEMENT (in order with the files; may repeat)\n"
               "  -             read the standard input here, as a script\n"
               "  -h, --help    print this and exit\n"
               "  --version     print the version and exit\n"
               "Type help at the prompt for the commands; man vroc for the manual.\n");
}

static int bad_usage(const char *fmt, const char *what)
{
    fprintf(stderr, "vroc: ");
    fprintf(stderr, fmt, what);
    fputc('\n', stderr);
    usage(stderr);
    return -1;
}

static void add_input(Options *o, InputKind kind, const char *arg)
{
    o->inputs[o->ninputs].kind = kind;
    o->inputs[o->ninputs++].arg = arg;
}

/* the letters of one "-bqi" word; -e takes the rest of the word or the
 * next one.  0, 1 (done: help), -1 (bad usage); *i moves past a taken word */
static int short_options(int argc, char **argv, int *i, Options *o)
{
    const char *a = argv[*i];
    int j;
    for (j = 1; a[j]; j++) {
        if (a[j] == 'b') o->bail = 1;
        else if (a[j] == 'q') o->quiet = 1;
        else if (a[j] == 'i') o->stay = 1;
        else if (a[j] == 'h') return usage(stdout), 1;
        else if (a[j] == 'e') {
            if (a[j + 1]) add_input(o, IN_STATEMENT, a + j + 1);
            else if (*i + 1 < argc) add_input(o, IN_STATEMENT, argv[++*i]);
            else return bad_usage("%s needs a statement", "-e");
            return 0;
        } else return bad_usage("unknown option '%s'", a);
    }
    return 0;
}

/* 0: run; 1: done (help, version), exit 0; -1: bad usage, exit 2 */
static int parse_options(int argc, char **argv, Options *o)
{
    int i, only_files = 0;
    memset(o, 0, sizeof *o);
    o->inputs = malloc((size_t)argc * sizeof *o->inputs);
    if (!o->inputs) return bad_usage("%s", "out of memory");
    for (i = 1; i < argc; i++) {
        const char *a = argv[i];
        int r;
        if (only_files || a[0] != '-') add_input(o, IN_FILE, a);
        else if (strcmp(a, "-") == 0) add_input(o, IN_STDIN, a);
        else if (strcmp(a, "--") == 0) only_files = 1;
        else if (strcmp(a, "--version") == 0) return printf("vroc %s\n", VROC_VERSION), 1;
        else if (strcmp(a, "--help") == 0) return usage(stdout), 1;
        else if ((r = short_options(argc, argv, &i, o)) != 0) return r;
    }
    return 0;
}

static int init_shell(Shell *sh, const Options *o)
{
    memset(sh, 0, sizeof *sh);
    sh->world = vrWorld_Create();
    if (!sh->world) return -1;
    sh->view = vrView_Default();
    snprintf(sh->frames_dir, sizeof sh->frames_dir, "frames");
    sh->selected = VR_NO_OBJECT;
    sh->quiet = o->quiet;
    sh->bail = o->bail;
    sh->interactive = isatty(STDIN_FILENO) && (o->ninputs == 0 || o->stay);
    return 0;
}

static void read_stdin(Shell *sh)
{
    Source src;
    struct stat sb;
    /* a pipe unbuffered: the wait for its next line (the window serviced
     * meanwhile, SPEC 9) then never misses a line already read ahead */
    if (fstat(STDIN_FILENO, &sb) == 0 && !S_ISREG(sb.st_mode)) setvbuf(stdin, NULL, _IONBF, 0);
    sh_source_init(&src, "<stdin>", "");
    sh_read_stream(sh, stdin, &src);
}

/* -e STATEMENT: its lines as a source named "-e", lines counted on over
 * every -e (a message says "-e:2" for the second) */
static void read_statement(Shell *sh, Source *src, const char *text)
{
    FILE *f = fmemopen((void *)text, strlen(text), "r");
    if (!f) {
        sh_error(sh, "cannot read the -e statement: out of memory");
        return;
    }
    sh_read_stream(sh, f, src);
    fclose(f);
}

static void read_inputs(Shell *sh, const Options *o)
{
    char err[SH_ERR_MAX];
    Source statements;
    int i;
    sh_source_init(&statements, "-e", "");
    for (i = 0; i < o->ninputs && !sh->quit && !sh->bailing; i++) {
        const Input *in = &o->inputs[i];
        if (in->kind == IN_STATEMENT) read_statement(sh, &statements, in->arg);
        else if (in->kind == IN_STDIN) read_stdin(sh);
        else if (sh_read_file(sh, in->arg, err, sizeof err) != 0) sh_error(sh, "%s", err);
    }
}

int main(int argc, char **argv)
{
    Options o;
    Shell sh;
    int r = parse_options(argc, argv, &o);
    if (r != 0) {
        free(o.inputs);
        return r > 0 ? 0 : 2;
    }
    if (init_shell(&sh, &o) != 0) {
        fprintf(stderr, "vroc: out of memory\n");
        free(o.inputs);
        return 1;
    }
    read_inputs(&sh, &o);
    /* -b ends a script at its first error; a person at the prompt goes on */
    if (!sh.quit && (o.ninputs == 0 || o.stay) && (sh.interactive || !sh.bailing)) {
        if (sh.interactive) sh_interactive(&sh);
        else read_stdin(&sh);
    }
    free(o.inputs);
    sh_display_close(&sh);
    sh_sound_close(&sh);
    vrTrackers_Close(sh.trackers);
    vrWorld_Destroy(sh.world);
    if (fflush(stdout) != 0) return 1;
    return sh.errors ? 1 : 0;
}
