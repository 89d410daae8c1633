/* resume.h — a saved file read, until its run goes live (save.h): the
 * owners' unheard states and the warm starts' validity kept for the
 * start, and the call the start makes to put them back.  Below start.c:
 * save.c, which reads the file, is above it. */
#ifndef VROC_RESUME_H
#define VROC_RESUME_H

#include "world_state.h"

/* what a read file leaves for the next start */
typedef struct vrResume {
    vrUpdate pending;        /* the states the owners had not heard of when it was saved */
    int warm;                /* the warm starts read belong to the next island step */
} vrResume;

/* the start, after the objects went live: what was read is put back */
int vrSave_Resume(vrWorld *w);
void vrSave_Free(vrWorld *w);
/* w->resume, made when missing; NULL when out of memory */
vrResume *vrSave_Resumed(vrWorld *w);

#endif
