/* save_sections.h — the sections of a saved file (save.h), each a writer
 * and a reader of `state WORD key=value ...` lines.
 *   save_world.c   clock, counters, random, gap, live
 *   save_body.c    body, warm, pending
 *   save_track.c   sample (the head's and the hand's samples still needed)
 *   save_sound.c   sound_pair (the collision sounds' refractory times)
 *   save_panel.c   panel (where the tool panel is, what the hand holds of it)
 * A new piece of state (the grab's, say) is a file of its own with a
 * writer and a reader declared here and one line in save.c's table. */
#ifndef VROC_SAVE_SECTIONS_H
#define VROC_SAVE_SECTIONS_H

#include "save.h"

void vrSave_WriteClock(vrWorld *w, int id, FILE *out);
int vrSave_ReadClock(vrWorld *w, int id, vrSaveLine *l, char *err, size_t n);
void vrSave_WriteCounters(vrWorld *w, int id, FILE *out);
int vrSave_ReadCounters(vrWorld *w, int id, vrSaveLine *l, char *err, size_t n);
void vrSave_WriteRandom(vrWorld *w, int id, FILE *out);
int vrSave_ReadRandom(vrWorld *w, int id, vrSaveLine *l, char *err, size_t n);
/* the last line: the saved run's objects go live as they were, so that
 * what follows the file acts on them as on the saving run's */
void vrSave_WriteLive(vrWorld *w, int id, FILE *out);
int vrSave_ReadLive(vrWorld *w, int id, vrSaveLine *l, char *err, size_t n);
/* an id left by a deleted object (ids order pairs and name islands) */
int vrSave_ReadGap(vrWorld *w, int id, vrSaveLine *l, char *err, size_t n);

void vrSave_WriteBody(vrWorld *w, int id, FILE *out);
int vrSave_ReadBody(vrWorld *w, int id, vrSaveLine *l, char *err, size_t n);
void vrSave_WriteWarm(vrWorld *w, int id, FILE *out);
int vrSave_ReadWarm(vrWorld *w, int id, vrSaveLine *l, char *err, size_t n);
void vrSave_WritePending(vrWorld *w, int id, FILE *out);
int vrSave_ReadPending(vrWorld *w, int id, vrSaveLine *l, char *err, size_t n);

/* an object named by key's value: its id, or an error naming the name */
int vrSave_GetObject(vrWorld *w, vrSaveLine *l, const char *key, int *id, char *err, size_t n);
/* key's unit quaternion, w first (to 1e-9: an edited one must stay a rotation; save_body.c) */
int vrSave_GetQuat(vrSaveLine *l, const char *key, quat *q, char *err, size_t n);

void vrSave_WriteSamples(vrWorld *w, int id, FILE *out);
int vrSave_ReadSample(vrWorld *w, int id, vrSaveLine *l, char *err, size_t n);
void vrSave_WriteSoundPairs(vrWorld *w, int id, FILE *out);
int vrSave_ReadSoundPair(vrWorld *w, int id, vrSaveLine *l, char *err, size_t n);
void vrSave_WritePanel(vrWorld *w, int id, FILE *out);
int vrSave_ReadPanel(vrWorld *w, int id, vrSaveLine *l, char *err, size_t n);

#endif
