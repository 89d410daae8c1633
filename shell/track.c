/* track.c — the trackers as the shell sees them (SPEC 8): `track FILE`
 * (a track file's samples played from now, in simulation time),
 * `trackers = URL` (live samples over LCM), `show head|hand`; the head
 * they move drives the view. */
#include <stdio.h>
#include <string.h>
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
    double fly[3];
    int i;
    if (vrWorld_TrackerPose(sh->world, VR_DEVICE_HEAD, &head) == 0) vrView_FromHead(&v, &head);
    vrWorld_FlyOffset(sh->world, fly);   /* the trigger flew the viewpoint (select = 0, SPEC 8) */
    for (i = 0; i < 3; i++) v.eye[i] += fly[i], v.look[i] += fly[i];
    return v;
}

/* `show head` and `show hand`: the tracker's pose now, or "none" */
int sh_show_tracker(Shell *sh, const char *name)
{
    vrDevice dev;
    vrTrackerSample s;
    char b[32];
    int i;
    if (strcmp(name, "head") == 0) dev = VR_DEVICE_HEAD;
    else if (strcmp(name, "hand") == 0) dev = VR_DEVICE_HAND;
    else return 0;
    if (vrWorld_TrackerPose(sh->world, dev, &s) != 0) {
        printf("%s none\n", name);
        return 1;
    }
    vrFormatDouble(b, s.t);
    printf("%s %s", name, b);
    for (i = 0; i < 3; i++) vrFormatDouble(b, s.position[i]), printf(" %s", b);
    for (i = 0; i < 4; i++) vrFormatDouble(b, s.orientation[i]), printf(" %s", b);
    printf(" %u\n", s.buttons);
    return 1;
}

/* `trackers = URL` (empty: stop listening).  In a script it waits for the
 * first sample, so that the run starts with the tracker's session. */
int run_trackers(Shell *sh, const Stmt *st, char *err, size_t n)
{
    char url[256];
    vrTrackers *tr;
    vrTrackers_Close(sh->trackers);
    sh->trackers = NULL;
    if (st->textlen == 0) return 0;
    snprintf(url, sizeof url, "%.*s", (int)st->textlen, st->text);
    if (vrTrackers_Open(&tr, sh->world, url, err, n) != 0) return -1;
    sh->trackers = tr;
    if (!sh->interactive && !vrTrackers_WaitFirst(tr, SH_TRACKER_FIRST_WAIT))
        sh_note(sh, "no tracker sample on %s within %g s; going on", url, SH_TRACKER_FIRST_WAIT);
    return 0;
}

/* before a frame: the live samples that reach its end (a script waits for
 * them, SPEC 8's "the run its track file gives"; the prompt keeps time) */
void sh_trackers_before_frame(Shell *sh)
{
    double T;
    if (!sh->trackers) return;
    T = vrWorld_NextFrameEnd(sh->world);
    vrTrackers_Poll(sh->trackers, T, sh->interactive ? 0 : SH_TRACKER_DEADLINE);
}
