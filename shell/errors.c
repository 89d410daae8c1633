/* errors.c — how the shell talks about problems (SPEC 1.4):
 * `vroc: FILE:LINE: message (read at FILE:LINE, ...)` on stderr, the
 * innermost source first.  Notes look the same with "note: " and do not
 * count as errors. */
#include <stdarg.h>
#include <stdio.h>
#include <string.h>
#include "shell.h"

void sh_location(const Shell *sh, char *buf, size_t n)
{
    if (sh->src) snprintf(buf, n, "%s:%ld", sh->src->name, sh->src->line);
    else snprintf(buf, n, "vroc");
}

/* " (read at b.cmd:7, read at <stdin>:21)": the sources that read this one */
static void put_chain(char *buf, size_t n, size_t *o, const Source *src)
{
    const Source *s;
    if (!src || !src->parent) return;
    for (s = src->parent; s && *o < n; s = s->parent)
        *o += (size_t)snprintf(buf + *o, n - *o, "%sread at %s:%ld", s == src->parent ? " (" : ", ", s->name, s->line);
    if (*o < n) *o += (size_t)snprintf(buf + *o, n - *o, ")");
}

/* one write per message: lines from several sources do not interleave */
static void report(const Shell *sh, const char *kind, const char *fmt, va_list ap)
{
    char buf[SH_ERR_MAX + 4 * VR_PATH_MAX];
    size_t o;
    if (sh->src) o = (size_t)snprintf(buf, sizeof buf, "vroc: %s:%ld: %s", sh->src->name, sh->src->line, kind);
    else o = (size_t)snprintf(buf, sizeof buf, "vroc: %s", kind);
    if (o < sizeof buf) o += (size_t)vsnprintf(buf + o, sizeof buf - o, fmt, ap);
    put_chain(buf, sizeof buf, &o, sh->src);
    if (o > sizeof buf - 2) o = sizeof buf - 2;
    buf[o++] = '\n';
    fflush(stdout);   /* keep stdout and stderr in order on a shared terminal */
    fwrite(buf, 1, o, stderr);
}

void sh_error(Shell *sh, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    report(sh, "", fmt, ap);
    va_end(ap);
    sh->errors++;
    if (sh->bail) sh->bailing = 1;
}

void sh_note(Shell *sh, const char *fmt, ...)
{
    va_list ap;
    if (sh->quiet) return;
    va_start(ap, fmt);
    report(sh, "note: ", fmt, ap);
    va_end(ap);
}

void sh_error_at(Shell *sh, const char *origin, const char *msg)
{
    fflush(stdout);
    fprintf(stderr, "vroc: %s: %s\n", origin, msg);
    sh->errors++;
    if (sh->bail) sh->bailing = 1;
}

int sh_resolve_path(const Shell *sh, const char *path, size_t len, char *out, size_t n)
{
    const char *dir = sh->src ? sh->src->dir : "";
    int w;
    if (path[0] == '/' || dir[0] == '\0') w = snprintf(out, n, "%.*s", (int)len, path);
    else w = snprintf(out, n, "%s/%.*s", dir, (int)len, path);
    return w >= 0 && (size_t)w < n ? 0 : -1;
}
