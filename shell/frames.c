/* frames.c — the frames the shell draws (SPEC 4): the display opened when
 * something needs it (src/display.c is the library's side), and once it is
 * open every frame drawn and written into the `frames` folder, numbered by
 * the frame count since `restart`; the `display` and `refresh` commands. */
#include <stdio.h>
#include "commands.h"

int sh_display_open(Shell *sh, char *err, size_t n)
{
    if (sh->display) return 0;
    return vrDisplay_Open(&sh->display, err, n);
}

/* the current frame, when a display is open; written when a folder is set;
 * the window (window.c) shows it too */
int sh_display_draw(Shell *sh, char *err, size_t n)
{
    vrStats st;
    vrView view;
    sh_window_frame(sh);
    if (!sh->display) return 0;
    view = sh_current_view(sh);
    if (vrDisplay_Render(sh->display, sh->world, &view, err, n) != 0) return -1;
    if (!sh->frames_dir[0]) return 0;
    vrWorld_GetStats(sh->world, &st);
    return vrDisplay_WriteFrames(sh->display, sh->frames_dir, st.frames, sh->frames_format, err, n);
}

void sh_display_close(Shell *sh)
{
    sh_window_close(sh);
    vrDisplay_Close(sh->display);
    sh->display = NULL;
}

/* `display` and `refresh` both open the display if needed and draw the
 * current frame (000000 before the first step) */
int run_display(Shell *sh, const Stmt *st, char *err, size_t n)
{
    (void)st;
    if (sh_display_open(sh, err, n) != 0) return -1;
    return sh_display_draw(sh, err, n);
}
