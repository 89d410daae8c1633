/* save.c — `save FILE` and `state ...` (SPEC 11): the whole state as a
 * command script that a fresh vroc reads to go on bit for bit.
 *
 * The shell writes what its command table knows: every setting and view
 * value, and each object's definition, as the statements that make them;
 * the library writes the rest (include/vroc.h vrWorld_WriteSave) as
 * `state WORD key=value ...` lines, which `state` hands back to it.
 * Numbers are the shortest decimals with the same bits (vrFormatExact).
 *   put_value        one statement of the table, from a struct's field
 *   write_settings   settings and view
 *   write_def        an object's definition (the library's callback)
 *   write_header     what the file is, and what it does not reconnect
 *   run_save, run_state
 */
#define _XOPEN_SOURCE 700   /* realpath */ /* NOLINT(bugprone-reserved-identifier): the feature test macro POSIX names */
#include <errno.h>
#include <limits.h>
#include <stdlib.h>
#include <string.h>
#include "commands.h"

static const char *const type_words[] = {"sphere", "cube", "superquadric", "polyhedron"};

static void put_num(FILE *out, double x)
{
    char b[32];
    vrFormatExact(b, x);
    fputs(b, out);
}

static void put_vec(FILE *out, const double *v, int count)
{
    int i;
    fputc('(', out);
    for (i = 0; i < count; i++) {
        if (i) fputs(", ", out);
        put_num(out, v[i]);
    }
    fputc(')', out);
}

/* `name = value` of command c from the field at c->offset of base */
static void put_value(FILE *out, const char *indent, const Command *c, const void *base)
{
    const void *f = (const char *)base + c->offset;   /* the field, of the kind c says */
    fprintf(out, "%s%s = ", indent, c->name);
    switch (c->kind) {
    case K_NUM: put_num(out, *(const double *)f); break;
    case K_INT:
        if (c->offset == offsetof(vrSettings, max_frames) && c->target == T_SETTINGS) fprintf(out, "%ld", *(const long *)f);
        else fprintf(out, "%d", *(const int *)f);
        break;
    case K_VEC3:
    case K_SCALE: put_vec(out, (const double *)f, 3); break;
    case K_IVEC3: fprintf(out, "(%d, %d, %d)", ((const int *)f)[0], ((const int *)f)[1], ((const int *)f)[2]); break;
    case K_IVEC2: fprintf(out, "(%d, %d)", ((const int *)f)[0], ((const int *)f)[1]); break;
    case K_AXIS:   /* force's magnitude, rotate's angle: the double after the vector */
        put_vec(out, (const double *)f, 3);
        fputc(' ', out);
        put_num(out, c->target == T_SETTINGS ? ((const vrSettings *)base)->force_mag : ((const vrObjectDef *)base)->rotate_angle);
        break;
    case K_TEXT:
    case K_WORD: fputs(f, out); break;
    case K_CHOICE:
        if (c->offset == offsetof(vrSettings, broadphase)) fputs(c->choices[*(const vrBroadphaseKind *)f], out);
        else fputs(c->choices[*(const vrDistribution *)f], out);
        break;
    case K_UINT64: fprintf(out, "%llu", *(const unsigned long long *)f); break;
    case K_NONE: break;
    }
    fputc('\n', out);
}

static void write_settings(Shell *sh, FILE *out)
{
    const vrSettings *s = vrWorld_Settings(sh->world);
    int i;
    fputs("\n# settings and view\n", out);
    for (i = 0; i < sh_ncommands; i++) {
        const Command *c = &sh_commands[i];
        if (c->target == T_SETTINGS) put_value(out, "", c, s);
        else if (c->target == T_VIEW) put_value(out, "", c, &sh->view);
    }
}

/* does attribute c go into d's definition?  mass only when given (else
 * the volume makes it), rotate only when set, file as an absolute path
 * (the save may lie elsewhere) */
static int wanted(const Command *c, const vrObjectDef *d)
{
    if (!(c->types & (1u << d->type))) return 0;
    if (c->offset == offsetof(vrObjectDef, mass)) return d->mass_set;
    if (c->kind == K_AXIS) return d->rotate_set;
    if (c->kind == K_TEXT) return d->file[0] != '\0';
    return 1;
}

static void write_def(void *ctx, FILE *out, vrObjectId id)
{
    Shell *sh = ctx;
    vrObjectDef d;
    int i;
    vrWorld_GetObjectDef(sh->world, id, &d);
    if (d.type == VR_POLYHEDRON && d.file[0]) {
        char real[PATH_MAX];
        if (realpath(d.file, real) && strlen(real) < sizeof d.file) memcpy(d.file, real, strlen(real) + 1);
    }
    fprintf(out, "%s %s\n", type_words[d.type], vrWorld_ObjectName(sh->world, id));
    for (i = 0; i < sh_ncommands; i++)
        if (sh_commands[i].target == T_OBJECT && wanted(&sh_commands[i], &d)) put_value(out, "  ", &sh_commands[i], &d);
}

/* A live tracker is a source, not state: reconnecting it would not give
 * the saved run again (its samples would come at other times), so the
 * reader takes the samples received, as `state sample` lines, and the
 * file says the subscription was left out. */
static void write_header(Shell *sh, FILE *out)
{
    vrStats s;
    vrWorld_GetStats(sh->world, &s);
    fprintf(out, "# vroc %s save: frame %ld, t = ", VROC_VERSION, s.frames);
    put_num(out, s.time);
    fprintf(out, " s, %d objects.\n# `vroc FILE` (or `read FILE` in a fresh vroc) goes on from here bit for bit;\n"
                 "# `man vroc`, SAVE, tells what each line holds and which may be edited.\n", s.objects);
    if (sh->trackers)
        fputs("# Live trackers (trackers = URL) were listened to: the samples they sent are saved below\n"
              "# as `state sample` lines; reading this file does not listen to them again.\n", out);
}

int run_save(Shell *sh, const Stmt *st, char *err, size_t n)
{
    char path[VR_PATH_MAX];
    FILE *out;
    int bad;
    if (sh_resolve_path(sh, st->text, st->textlen, path, sizeof path) != 0) {
        snprintf(err, n, "file name too long");
        return -1;
    }
    if (!(out = fopen(path, "w"))) {
        snprintf(err, n, "cannot write '%s': %s", path, strerror(errno));
        return -1;
    }
    write_header(sh, out);
    write_settings(sh, out);
    bad = vrWorld_WriteSave(sh->world, out, write_def, sh);
    if (fclose(out) != 0 || bad) {
        snprintf(err, n, "cannot write '%s': %s", path, strerror(errno));
        return -1;
    }
    return 0;
}

int run_state(Shell *sh, const Stmt *st, char *err, size_t n)
{
    return vrWorld_ReadState(sh->world, sh->selected, st->text, st->textlen, err, n);
}
