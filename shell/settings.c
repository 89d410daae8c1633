/* settings.c — system settings (thesis table A.5 and the SPEC 1.2
 * extensions) through vrWorld_Settings / vrWorld_SetSettings, the view
 * kept by the shell (SPEC 4), and the machine-readable outputs. */
#include <stdio.h>
#include <string.h>
#include "commands.h"

static void store_text(char *field, size_t size, const Stmt *st)
{
    snprintf(field, size, "%.*s", (int)st->textlen, st->text);
}

static void store_setting(vrSettings *s, const Stmt *st)
{
    const Command *c = st->cmd;
    if (c->offset == offsetof(vrSettings, max_frames)) s->max_frames = (long)st->v[0];
    else if (c->offset == offsetof(vrSettings, lcm_url)) store_text(s->lcm_url, sizeof s->lcm_url, st);
    else if (c->offset == offsetof(vrSettings, collision_sound))
        store_text(s->collision_sound, sizeof s->collision_sound, st);
    else if (c->offset == offsetof(vrSettings, broadphase))
        s->broadphase = st->choice == 0 ? VR_BROADPHASE_SWEEP : VR_BROADPHASE_TREE;
    else if (c->kind == K_CHOICE) s->distribution = st->choice == 0 ? VR_DIST_ROUND_ROBIN : VR_DIST_IMPROVED;
    else if (c->kind == K_UINT64) s->seed = st->u;
    else sh_store_number(s, st);
    if (c->kind == K_AXIS) s->force_mag = st->v[3];
}

int run_setting(Shell *sh, const Stmt *st, char *err, size_t n)
{
    vrSettings s = *vrWorld_Settings(sh->world);
    size_t at = st->cmd->offset;
    store_setting(&s, st);
    if (vrWorld_SetSettings(sh->world, &s, err, n) != 0) return -1;
    /* who sets a cap chose it: the first clamp's note is for the defaults */
    if (at == offsetof(vrSettings, max_linear) || at == offsetof(vrSettings, max_angular)) sh->clamp_noted = 1;
    return 0;
}

int run_gravity(Shell *sh, const Stmt *st, char *err, size_t n)
{
    vrSettings s = *vrWorld_Settings(sh->world);
    (void)st;
    s.force_dir[0] = 0, s.force_dir[1] = 0, s.force_dir[2] = -1;
    s.force_mag = 9.8;
    return vrWorld_SetSettings(sh->world, &s, err, n);
}

int run_view(Shell *sh, const Stmt *st, char *err, size_t n)
{
    (void)err, (void)n;
    if (st->cmd->kind == K_IVEC2) {
        sh->view.width = (int)st->v[0];
        sh->view.height = (int)st->v[1];
    } else sh_store_number(&sh->view, st);
    return 0;
}

int run_reset(Shell *sh, const Stmt *st, char *err, size_t n)
{
    vrView d = vrView_Default();
    (void)st, (void)err, (void)n;
    memcpy(sh->view.eye, d.eye, sizeof d.eye);
    memcpy(sh->view.look, d.look, sizeof d.look);
    memcpy(sh->view.up, d.up, sizeof d.up);
    vrWorld_ClearTracker(sh->world, VR_DEVICE_HEAD);   /* the head no longer moves the view */
    return 0;
}

int run_frames(Shell *sh, const Stmt *st, char *err, size_t n)
{
    char dir[VR_PATH_MAX];
    if (st->textlen == 0) {   /* stops writing, opens nothing */
        sh->frames_dir[0] = '\0';
        return 0;
    }
    if (sh_resolve_path(sh, st->text, st->textlen, dir, sizeof dir) != 0) {
        snprintf(err, n, "folder name too long");
        return -1;
    }
    if (sh_display_open(sh, err, n) != 0) return -1;
    memcpy(sh->frames_dir, dir, sizeof dir);
    return 0;
}

int run_frames_format(Shell *sh, const Stmt *st, char *err, size_t n)
{
    (void)err, (void)n;
    sh->frames_format = st->choice == 1 ? VR_FRAMES_PNG : VR_FRAMES_PPM;
    return 0;
}

static int stdout_ok(char *err, size_t n)
{
    if (fflush(stdout) == 0 && !ferror(stdout)) return 0;
    snprintf(err, n, "cannot write to the standard output");
    clearerr(stdout);
    return -1;
}

int run_dump(Shell *sh, const Stmt *st, char *err, size_t n)
{
    (void)st;
    if (vrWorld_WriteDump(sh->world, stdout) != 0 && !ferror(stdout)) {
        snprintf(err, n, "out of memory");
        return -1;
    }
    return stdout_ok(err, n);
}

int run_stats(Shell *sh, const Stmt *st, char *err, size_t n)
{
    (void)st;
    vrWorld_WriteStats(sh->world, stdout);
    return stdout_ok(err, n);
}
