/* save.h — `save FILE` and the `state` lines that read it back (SPEC 11).
 *
 * A saved file is a command script: the shell writes the settings and
 * each object's definition (its command table knows their words), and
 * the library the rest of the state as `state WORD key=value ...` lines,
 * one section per piece of state, each section a writer and a reader in
 * one table (save.c): the clock and counters, the random stream, each
 * body's anchor and rest, the warm starts, the states the owners had not
 * heard of, the trackers' samples, the sounds' refractory times.  New
 * state (the grab's) is one more section: save_sections.h tells how.
 *
 * Reading: the world-wide lines act on the world at once; a body's line
 * stays on its object (saved.h) until the start makes it live; the start
 * then calls vrSave_Resume, which puts back what a fresh start makes
 * anew (the owners' unheard states, the warm starts' validity, the rest
 * count).  Saving retires the pair owners, as a change of `gps` does, so
 * that the saving run goes on from exactly the state the file holds: both
 * make fresh owners at the next start and do the same work, counters and
 * all. */
#ifndef VROC_SAVE_H
#define VROC_SAVE_H

#include "world_state.h"
#include "save_line.h"
#include "resume.h"

/* one piece of state: written after each object's definition (per_object)
 * or once after all objects; read from `state WORD ...` (id: the selected
 * object, VR_NO_OBJECT when none) */
typedef struct vrSaveSection {
    const char *word;
    const char *keys;        /* every key its lines may hold, blank-separated: a line with
                                another changes nothing */
    int per_object;
    void (*write)(vrWorld *w, int id, FILE *out);
    int (*read)(vrWorld *w, int id, vrSaveLine *l, char *err, size_t n);
} vrSaveSection;

#endif
