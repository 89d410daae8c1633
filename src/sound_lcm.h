/* sound_lcm.h — collision sound events as vroc.sound_t messages on
 * VROC_SOUND (SPEC 8): published by the live trackers (live.c) and by the
 * coordinator of workers on an LCM network URL (parallel/sgp.c), one
 * message per event, fire and forget. */
#ifndef VROC_SOUND_LCM_H
#define VROC_SOUND_LCM_H

#include <lcm/lcm.h>
#include "vroc.h"

#define VR_CH_SOUND "VROC_SOUND"

/* the sound settings name: collision_sound, or the built-in when it is empty */
const char *vrSounds_Name(const vrSettings *s);
/* ev[0..n) as sound `sound`; -1 when LCM refused one */
int vrSounds_Publish(lcm_t *lcm, const vrSoundEvent *ev, int n, const char *sound);

#endif
