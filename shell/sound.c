/* sound.c — `sound_log = FILE` (SPEC 8): each frame's collision sound
 * events written as lines t,sound,volume,x,y,z,speed, which
 * tools/vroc-sound renders to a WAV. */
#include <stdio.h>
#include <string.h>
#include "commands.h"

void sh_sound_close(Shell *sh)
{
    if (sh->sound_log) fclose(sh->sound_log);
    sh->sound_log = NULL;
}

int run_sound_log(Shell *sh, const Stmt *st, char *err, size_t n)
{
    char path[VR_PATH_MAX];
    FILE *f;
    if (st->textlen == 0) {   /* stops writing */
        sh_sound_close(sh);
        return 0;
    }
    if (sh_resolve_path(sh, st->text, st->textlen, path, sizeof path) != 0) {
        snprintf(err, n, "file name too long");
        return -1;
    }
    f = fopen(path, "w");
    if (!f) {
        snprintf(err, n, "cannot write the sound log %s", path);
        return -1;
    }
    sh_sound_close(sh);
    sh->sound_log = f;
    fprintf(f, "# t,sound,volume,x,y,z,speed\n");
    return 0;
}

static void put_number(FILE *f, double x, char sep)
{
    char buf[32];
    vrFormatDouble(buf, x);
    fprintf(f, "%s%c", buf, sep);
}

/* the last frame's events, when a log is open */
int sh_sound_frame(Shell *sh, char *err, size_t n)
{
    const vrSoundEvent *ev;
    const char *name = vrWorld_Settings(sh->world)->collision_sound;
    int k, count = vrWorld_FrameSounds(sh->world, &ev);
    if (!name[0]) name = VR_SOUND_DEFAULT;
    if (sh->trackers && vrTrackers_PublishSounds(sh->trackers, ev, count, name) != 0) {
        snprintf(err, n, "cannot publish the sound events on VROC_SOUND");
        return -1;
    }
    if (!sh->sound_log) return 0;
    for (k = 0; k < count; k++) {
        put_number(sh->sound_log, ev[k].t, ',');
        fprintf(sh->sound_log, "%s,", name);
        put_number(sh->sound_log, ev[k].volume, ',');
        put_number(sh->sound_log, ev[k].position[0], ',');
        put_number(sh->sound_log, ev[k].position[1], ',');
        put_number(sh->sound_log, ev[k].position[2], ',');
        put_number(sh->sound_log, ev[k].speed, '\n');
    }
    if (fflush(sh->sound_log) == 0 && !ferror(sh->sound_log)) return 0;
    snprintf(err, n, "cannot write the sound log");
    sh_sound_close(sh);
    return -1;
}
