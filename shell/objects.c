/* objects.c — object commands and attributes (thesis tables A.1-A.4,
 * SPEC 1.1): create or select, edit the selected object's definition
 * through vrWorld_GetObjectDef / vrWorld_SetObjectDef, show, delete,
 * random. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "commands.h"
#include "lexer.h"

static const char *const type_names[] = {"sphere", "cube", "superquadric", "polyhedron"};

static vrObjectType type_of_command(const Command *c)
{
    int t;
    for (t = VR_SPHERE; t < VR_POLYHEDRON; t++)
        if (strcmp(c->name, type_names[t]) == 0) break;
    return (vrObjectType)t;
}

/* a reused name selects the original object, whatever the type word (the
 * thesis's rule); a different type word says so, as a newcomer typing
 * `cube ball` after `sphere ball` expects a new cube */
int run_object(Shell *sh, const Stmt *st, char *err, size_t n)
{
    vrObjectId id = vrWorld_FindObject(sh->world, st->name);
    vrObjectType want = type_of_command(st->cmd);
    vrObjectDef d;
    if (id == VR_NO_OBJECT && sh_reserved_name(st->name)) {
        snprintf(err, n, "'%s' is a reserved word (show %s prints the tool panel), not an object name", st->name, st->name);
        return -1;
    }
    if (id == VR_NO_OBJECT) {
        if (vrWorld_CreateObject(sh->world, st->name, want, &id, err, n) != 0) return -1;
    } else if (vrWorld_GetObjectDef(sh->world, id, &d) == 0 && d.type != want)
        sh_note(sh, "'%s' is an existing %s: selected it (no %s made; delete %s first for a new one)", st->name,
                type_names[d.type], type_names[want], st->name);
    sh->selected = id;
    return 0;
}

/* K_NUM, K_INT, K_VEC3, K_IVEC3 values into the field at c->offset of base */
void sh_store_number(void *base, const Stmt *st)
{
    void *field = (char *)base + st->cmd->offset;
    int i;
    switch (st->cmd->kind) {
    case K_NUM: *(double *)field = st->v[0]; break;
    case K_INT: *(int *)field = (int)st->v[0]; break;
    case K_VEC3:
    case K_SCALE:
    case K_AXIS:
        for (i = 0; i < 3; i++) ((double *)field)[i] = st->v[i];
        break;
    case K_IVEC3:
        for (i = 0; i < 3; i++) ((int *)field)[i] = (int)st->v[i];
        break;
    default: break;
    }
}

static int store_attr(Shell *sh, vrObjectDef *d, const Stmt *st, char *err, size_t n)
{
    if (st->cmd->kind == K_TEXT) {   /* file = path.off, relative to the scene file */
        if (sh_resolve_path(sh, st->text, st->textlen, d->file, sizeof d->file) != 0) {
            snprintf(err, n, "file name too long");
            return -1;
        }
        return 0;
    }
    sh_store_number(d, st);
    if (st->cmd->offset == offsetof(vrObjectDef, mass)) d->mass_set = 1;   /* wins over volume */
    if (st->cmd->kind == K_AXIS) {
        d->rotate_angle = st->v[3];
        d->rotate_set = 1;
    }
    return 0;
}

int run_attr(Shell *sh, const Stmt *st, char *err, size_t n)
{
    vrObjectDef d;
    if (sh->selected == VR_NO_OBJECT || vrWorld_GetObjectDef(sh->world, sh->selected, &d) != 0) {
        snprintf(err, n, "no object selected for '%s' (sphere, cube, superquadric or polyhedron NAME selects one)",
                 st->cmd->name);
        return -1;
    }
    if (!(st->cmd->types & (1u << d.type))) {
        sh_note(sh, "'%s' does not apply to %s '%s'; ignored", st->cmd->name, type_names[d.type],
                vrWorld_ObjectName(sh->world, sh->selected));
        return 0;
    }
    if (store_attr(sh, &d, st, err, n) != 0) return -1;
    return vrWorld_SetObjectDef(sh->world, sh->selected, &d, err, n);
}

/* ---- show, delete ------------------------------------------------------------- */

static void put_doubles(const double *v, int count)
{
    char b[32];
    int i;
    putchar('(');
    for (i = 0; i < count; i++) {
        vrFormatDouble(b, v[i]);
        printf("%s%s", i ? ", " : "", b);
    }
    putchar(')');
}

static void show_attr(const Command *c, const vrObjectDef *d)
{
    const char *field = (const char *)d + c->offset;
    char b[32];
    printf("%s =%s", c->name, c->kind == K_TEXT && !field[0] ? "" : " ");
    if (c->offset == offsetof(vrObjectDef, mass)) {
        vrFormatDouble(b, d->mass_set ? d->mass : d->volume);
        fputs(b, stdout);
    } else if (c->kind == K_NUM) {
        /* cppcheck-suppress invalidPointerCast ; field is a double of vrObjectDef, at its offsetof */
        vrFormatDouble(b, *(const double *)field);
        fputs(b, stdout);
    } else if (c->kind == K_INT) printf("%d", *(const int *)field);
    /* cppcheck-suppress invalidPointerCast ; field is a double[3] of vrObjectDef, at its offsetof */
    else if (c->kind == K_VEC3 || c->kind == K_SCALE) put_doubles((const double *)field, 3);
    else if (c->kind == K_IVEC3) printf("(%d, %d, %d)", d->color[0], d->color[1], d->color[2]);
    else if (c->kind == K_AXIS) {
        put_doubles(d->rotate_axis, 3);
        vrFormatDouble(b, d->rotate_set ? d->rotate_angle : 0.0);
        printf(" %s", b);
    } else fputs(field, stdout);
    putchar('\n');
}

/* "no object named 'x'", with the nearest existing name */
static int no_such_object(Shell *sh, const char *name, char *err, size_t n)
{
    int count = vrWorld_ObjectCount(sh->world), i;
    vrObjectId *ids = malloc((size_t)(count ? count : 1) * sizeof *ids);
    const char **names = malloc((size_t)(count ? count : 1) * sizeof *names);
    const char *near = NULL;
    if (ids && names) {
        vrWorld_ObjectList(sh->world, ids, count);
        for (i = 0; i < count; i++) names[i] = vrWorld_ObjectName(sh->world, ids[i]);
        near = lx_suggest(name, strlen(name), names, count);
    }
    if (near) snprintf(err, n, "no object named '%s' (did you mean '%s'?)", name, near);
    else snprintf(err, n, "no object named '%s'", name);
    free(ids);
    free(names);
    return -1;
}

int run_show(Shell *sh, const Stmt *st, char *err, size_t n)
{
    vrObjectId id = vrWorld_FindObject(sh->world, st->name);
    vrObjectDef d;
    int i;
    if (sh_show_tracker(sh, st->name) || sh_show_panel(sh, st->name)) return 0;   /* head, hand, panel: reserved (SPEC 8) */
    if (id == VR_NO_OBJECT || vrWorld_GetObjectDef(sh->world, id, &d) != 0) return no_such_object(sh, st->name, err, n);
    printf("name = %s\ntype = %s\n", st->name, type_names[d.type]);
    for (i = 0; i < sh_ncommands; i++) {
        const Command *c = &sh_commands[i];
        if (c->target == T_OBJECT && (c->types & (1u << d.type))) show_attr(c, &d);
    }
    return 0;
}

int run_delete(Shell *sh, const Stmt *st, char *err, size_t n)
{
    vrObjectId id = vrWorld_FindObject(sh->world, st->name);
    if (id == VR_NO_OBJECT) return no_such_object(sh, st->name, err, n);
    if (vrWorld_DeleteObject(sh->world, id) != 0) {
        snprintf(err, n, "cannot delete '%s' (out of memory)", st->name);
        return -1;
    }
    if (sh->selected == id) sh->selected = VR_NO_OBJECT;
    return 0;
}

int run_random(Shell *sh, const Stmt *st, char *err, size_t n)
{
    return vrWorld_AddRandom(sh->world, (int)st->v[0], err, n);
}
