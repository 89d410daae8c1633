/* main.c — `vroc [options] [file...]`: options and modes (SPEC 1).
 *
 * As in SQLite's shell and lua.c, isatty(0) decides: a terminal and no
 * files gives the banner and the prompt; otherwise statements are read
 * as a script, silently.  Files on the command line are read in order,
 * then vroc exits, or with -i goes on at the prompt.  Exit status: 0 when
 * every statement succeeded, 1 after any error, 2 for bad usage.
 */
#include <stdio.h>
#include <sys/stat.h>
#include <string.h>
#include <unistd.h>
#include "shell.h"

typedef struct Options {
    int bail, quiet, stay, nfiles;
    char **files;
} Options;

static void usage(FILE *f)
{
    fprintf(f, "usage: vroc [-b] [-q] [-i] [file...]\n"
               "Virtual and Real Object Collisions: reads commands from the files, or\n"
               "from the standard input (a prompt when it is a terminal).\n"
               "  -b         stop at the first error (bail)\n"
               "  -q         quiet: do not print notes\n"
               "  -i         after the files, stay at the prompt\n"
               "  -h, --help print this and exit\n"
               "  --version  print the version and exit\n"
               "Type help at the prompt for the commands; man vroc for the manual.\n");
}

/* 0: run; 1: done (help, version), exit 0; -1: bad usage, exit 2 */
static int parse_options(int argc, char **argv, Options *o)
{
    int i, j;
    memset(o, 0, sizeof *o);
    for (i = 1; i < argc && argv[i][0] == '-' && argv[i][1]; i++) {
        const char *a = argv[i];
        if (strcmp(a, "--") == 0) {
            i++;
            break;
        }
        if (strcmp(a, "--version") == 0) return printf("vroc %s\n", VROC_VERSION), 1;
        if (strcmp(a, "--help") == 0) return usage(stdout), 1;
        for (j = 1; a[j]; j++) {
            if (a[j] == 'b') o->bail = 1;
            else if (a[j] == 'q') o->quiet = 1;
            else if (a[j] == 'i') o->stay = 1;
            else if (a[j] == 'h') return usage(stdout), 1;
            else {
                fprintf(stderr, "vroc: unknown option '%s'\n", a);
                usage(stderr);
                return -1;
            }
        }
    }
    o->files = argv + i;
    o->nfiles = argc - i;
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
    sh->interactive = isatty(STDIN_FILENO) && (o->nfiles == 0 || o->stay);
    return 0;
}

static void read_files(Shell *sh, const Options *o)
{
    char err[SH_ERR_MAX];
    int i;
    for (i = 0; i < o->nfiles && !sh->quit && !sh->bailing; i++)
        if (sh_read_file(sh, o->files[i], err, sizeof err) != 0) sh_error(sh, "%s", err);
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

int main(int argc, char **argv)
{
    Options o;
    Shell sh;
    int r = parse_options(argc, argv, &o);
    if (r != 0) return r > 0 ? 0 : 2;
    if (init_shell(&sh, &o) != 0) {
        fprintf(stderr, "vroc: out of memory\n");
        return 1;
    }
    read_files(&sh, &o);
    /* -b ends a script at its first error; a person at the prompt goes on */
    if (!sh.quit && (o.nfiles == 0 || o.stay) && (sh.interactive || !sh.bailing)) {
        if (sh.interactive) sh_interactive(&sh);
        else read_stdin(&sh);
    }
    sh_display_close(&sh);
    sh_sound_close(&sh);
    vrTrackers_Close(sh.trackers);
    vrWorld_Destroy(sh.world);
    if (fflush(stdout) != 0) return 1;
    return sh.errors ? 1 : 0;
}
