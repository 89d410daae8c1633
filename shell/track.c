/* track.c — `track FILE` (SPEC 8): a track file's samples played from
 * now, in simulation time; the head they move drives the view. */
#include <stdio.h>
#include "commands.h"

int run_track(Shell *sh, const Stmt *st, char *err, size_t n)
{
    char path[VR_PATH_MAX];
    if (sh_resolve_path(sh, st->text, st->textlen, path, sizeof path) != 0) {
        snprintf(err, n, "file name too long");
        return -1;
    }
    return vrWorld_ReadTrack(sh->world, path, err, n);
}

/* the view of this frame: the tracked head's, when there is one */
vrView sh_current_view(const Shell *sh)
{
    vrView v = sh->view;
    vrTrackerSample head;
    if (vrWorld_TrackerPose(sh->world, VR_DEVICE_HEAD, &head) == 0) vrView_FromHead(&v, &head);
    return v;
}
