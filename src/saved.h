/* saved.h — an object's state read from a saved file (SPEC 11), kept on
 * the object until it goes live: wherever the object is placed before
 * that (`dump` before a step, the start), it is placed here, not where
 * its definition says.  save.c reads it; vrObject_Place (build.c) uses it;
 * the start (vrSave_Resume) lets it go. */
#ifndef VROC_SAVED_H
#define VROC_SAVED_H

#include "table.h"

typedef struct vrSavedBody {
    vrBodyState anchor;       /* raw: the body's anchor bit for bit, with its rest and island */
    vrPose frame_pose;        /* the last frame end's pose (rest, SPEC 3.5) */
    int have_frame_pose;
    int quiet_frames, slow_frames; /* the rest test's window (rest.c) */
    double slow_start;
    int overlap_owed;         /* a start check owed (SPEC 1.4) */
} vrSavedBody;

/* o placed at its saved state (o->saved) */
void vrSaved_Place(vrObject *o, const vrFlight *f);

#endif
