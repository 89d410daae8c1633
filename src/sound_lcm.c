/* sound_lcm.c — sound events on VROC_SOUND (SPEC 8), for whoever holds an
 * LCM instance: the live trackers and the workers' coordinator. */
#include "sound_lcm.h"
#include "vroc_sound_t.h"

const char *vrSounds_Name(const vrSettings *s)
{
    return s->collision_sound[0] ? s->collision_sound : VR_SOUND_DEFAULT;
}

int vrSounds_Publish(lcm_t *lcm, const vrSoundEvent *ev, int n, const char *sound)
{
    int k;
    for (k = 0; k < n; k++) {
        vroc_sound_t m;
        int i;
        m.t = ev[k].t;
        m.sound = (char *)sound;   /* lcm-gen's string is not const; it is only read */
        m.volume = ev[k].volume;
        for (i = 0; i < 3; i++) m.position[i] = ev[k].position[i];
        m.speed = ev[k].speed;
        if (vroc_sound_t_publish(lcm, VR_CH_SOUND, &m) != 0) return -1;
    }
    return 0;
}
