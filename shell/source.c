/* source.c — reading statements from streams: files on the command line,
 * `read FILE` (nested, relative to the reading file, cycles refused) and
 * stdin in batch mode.  Like SQLite's `.read`, a file is the same input
 * loop on another FILE*.  Lines are read with getline: any length. */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include "commands.h"

void sh_source_init(Source *src, const char *name, const char *dir)
{
    memset(src, 0, sizeof *src);
    snprintf(src->name, sizeof src->name, "%s", name);
    snprintf(src->dir, sizeof src->dir, "%s", dir);
}

int sh_read_stream(Shell *sh, FILE *f, Source *src)
{
    char *buf = NULL;
    size_t cap = 0;
    ssize_t len;
    Source *outer = sh->src;
    src->parent = outer;
    src->depth = outer ? outer->depth + 1 : 0;
    sh->src = src;
    /* a pipe may keep the shell waiting: the window is serviced meanwhile */
    while (!sh->quit && !sh->bailing && (sh_wait_input(sh, fileno(f)), (len = getline(&buf, &cap, f)) >= 0)) {
        src->line++;
        sh_exec_line(sh, buf, (size_t)len);
    }
    if (ferror(f) && !sh->quit && !sh->bailing) sh_error(sh, "read error after this line: %s", strerror(errno));
    free(buf);
    sh->src = outer;
    return 0;
}

/* the folder of a path, where its relative paths start */
static void dir_of(const char *path, char *dir, size_t n)
{
    const char *slash = strrchr(path, '/');
    if (!slash) snprintf(dir, n, "%s", "");
    else if (slash == path) snprintf(dir, n, "/");
    else snprintf(dir, n, "%.*s", (int)(slash - path), path);
}

/* a file already open further out in the chain: reading it again would loop */
static const Source *reader_of(const Shell *sh, const struct stat *st)
{
    const Source *s;
    for (s = sh->src; s; s = s->parent)
        if (s->has_id && s->dev == st->st_dev && s->ino == st->st_ino) return s;
    return NULL;
}

static int open_source(Shell *sh, const char *path, FILE **fp, struct stat *st, char *err, size_t n)
{
    const Source *again;
    FILE *f = fopen(path, "r");
    if (!f) {
        snprintf(err, n, "cannot read '%s': %s", path, strerror(errno));
        return -1;
    }
    if (fstat(fileno(f), st) != 0 || S_ISDIR(st->st_mode)) {
        snprintf(err, n, "cannot read '%s': %s", path, S_ISDIR(st->st_mode) ? "it is a directory" : strerror(errno));
        fclose(f);
        return -1;
    }
    again = reader_of(sh, st);
    if (again) {
        if (strcmp(path, again->name) == 0)
            snprintf(err, n, "'%s' is already being read: a file that reads itself is not read again", path);
        else
            snprintf(err, n, "'%s' is '%s', which is already being read: a file that reads itself is not read again",
                     path, again->name);
        fclose(f);
        return -1;
    }
    if (sh->src && sh->src->depth + 1 >= SH_READ_DEPTH_MAX) {
        snprintf(err, n, "cannot read '%s': reads nested more than %d deep", path, SH_READ_DEPTH_MAX);
        fclose(f);
        return -1;
    }
    *fp = f;
    return 0;
}

int sh_read_file(Shell *sh, const char *path, char *err, size_t n)
{
    Source *src;
    struct stat st;
    FILE *f;
    char dir[VR_PATH_MAX];
    if (open_source(sh, path, &f, &st, err, n) != 0) return -1;
    src = malloc(sizeof *src);   /* two paths each: off the stack for deep nesting */
    if (!src) {
        fclose(f);
        snprintf(err, n, "out of memory");
        return -1;
    }
    dir_of(path, dir, sizeof dir);
    sh_source_init(src, path, dir);
    src->dev = st.st_dev;
    src->ino = st.st_ino;
    src->has_id = 1;
    sh_read_stream(sh, f, src);
    fclose(f);
    free(src);
    return 0;
}

int run_read(Shell *sh, const Stmt *st, char *err, size_t n)
{
    char path[VR_PATH_MAX];
    if (sh_resolve_path(sh, st->text, st->textlen, path, sizeof path) != 0) {
        snprintf(err, n, "file name too long");
        return -1;
    }
    return sh_read_file(sh, path, err, n);
}

int run_quit(Shell *sh, const Stmt *st, char *err, size_t n)
{
    (void)st, (void)err, (void)n;
    sh->quit = 1;
    return 0;
}
