/* panel.c — the virtual tool panel as the shell sees it (SPEC 8): `show
 * panel`, `panel` kept out of the object names, and the panel's stop,
 * play and step presses acted on after each frame (the library records
 * them; time is the shell's: start, stop, step, simulate.c).
 *
 *   act            one press on the run going on (man vroc, TOOL PANEL)
 */
#include <stdio.h>
#include <string.h>
#include "commands.h"

int sh_reserved_name(const char *name)
{
    return strcmp(name, "panel") == 0;
}

/* `show panel`: one line per control, NAME x y z, in world coordinates
 * (a slider's: its knob's); `panel off` when settings.panel = 0 */
int sh_show_panel(Shell *sh, const char *name)
{
    int c, i;
    if (!sh_reserved_name(name)) return 0;
    if (!vrWorld_Settings(sh->world)->panel) {
        printf("panel off\n");
        return 1;
    }
    for (c = 0; c < VR_PANEL_CONTROLS; c++) {
        double x[3];
        char b[32];
        vrWorld_PanelControl(sh->world, (vrPanelControl)c, x);
        fputs(vrPanel_ControlName((vrPanelControl)c), stdout);
        for (i = 0; i < 3; i++) vrFormatDouble(b, x[i]), printf(" %s", b);
        putchar('\n');
    }
    return 1;
}

/* stop: time stops after this frame (a real-time run, a script's start or
 * the rest of a step n); play: time runs as after `start` (at the prompt
 * in real time; in a script the step n going on becomes a start: until
 * all rest or max_frames frames); step: time stops, and one frame more */
static void act(Shell *sh, vrPanelControl c, ShRun *run)
{
    char err[SH_ERR_MAX];
    if (c == VR_PANEL_STOP || c == VR_PANEL_STEP) {
        sh->running = 0;
        run->left = c == VR_PANEL_STEP;
        run->until_rest = 0;
    } else if (c == VR_PANEL_PLAY && sh->interactive) {
        if (sh->running) return;
        if (sh_run_realtime(sh, err, sizeof err) != 0) sh_error_at(sh, "panel", err);
        else snprintf(sh->run_origin, sizeof sh->run_origin, "panel");
    } else if (c == VR_PANEL_PLAY && !run->until_rest) {
        run->left = vrWorld_Settings(sh->world)->max_frames;
        run->until_rest = 1;
    }
}

void sh_panel_requests(Shell *sh, ShRun *run)
{
    vrPanelControl req[VR_PANEL_REQUESTS_MAX];
    int k, n = vrWorld_PanelRequests(sh->world, req, VR_PANEL_REQUESTS_MAX);
    for (k = 0; k < n; k++) act(sh, req[k], run);
}
