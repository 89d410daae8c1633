/* resume.c — what a saved file read leaves for the start (resume.h).
 *   release_saved    the bodies read let go of their saved states
 *   merge_pending    the owners' unheard states
 *   vrSave_Resume    all of it, after the objects went live
 */
#include <stdlib.h>
#include "resume.h"
#include "saved.h"

vrResume *vrSave_Resumed(vrWorld *w)
{
    if (!w->resume && (w->resume = calloc(1, sizeof *w->resume))) vrUpdate_Init(&w->resume->pending);
    return w->resume;
}

void vrSave_Free(vrWorld *w)
{
    if (!w->resume) return;
    vrUpdate_Free(&w->resume->pending);
    free(w->resume);
    w->resume = NULL;
}

/* the bodies read let go of their saved states; 1 when there were any */
static int release_saved(vrWorld *w)
{
    int i, any = 0;
    for (i = 0; i < w->table.n; i++) {
        vrObject *o = w->table.obj[i];
        if (!o || !o->saved || !o->live) continue;
        o->overlap_owed = o->saved->overlap_owed;
        free(o->saved);
        o->saved = NULL;
        any = 1;
    }
    return any;
}

/* the owners' unheard states: the saved ones, and those of objects that
 * went live placed by their definitions (added to the file by hand) */
static int merge_pending(vrWorld *w, const vrResume *r)
{
    int i, k = 0;
    for (i = 0; i < w->pending.n; i++) {
        const vrObject *o = vrWorld_Object(w, w->pending.body[i].id);
        if (o && !o->saved) w->pending.body[k++] = w->pending.body[i];
    }
    w->pending.n = k;
    for (i = 0; i < r->pending.n; i++) {
        vrBodyState *st;
        vrObject *o = vrWorld_Object(w, r->pending.body[i].id);
        if (!o || !o->live) continue;
        if (!(st = vrUpdate_Body(&w->pending, &o->body, w->t))) return -1;
        *st = r->pending.body[i];
    }
    return 0;
}

int vrSave_Resume(vrWorld *w)
{
    vrResume *r = w->resume;
    int i;
    if (r && merge_pending(w, r) != 0) return -1;
    if (release_saved(w)) {
        w->may_rest = 0;                 /* rest.c counts the resting at frame ends */
        for (i = 0; i < w->table.n; i++)
            if (w->table.obj[i] && w->table.obj[i]->live) w->may_rest += w->table.obj[i]->body.resting;
    }
    if (!r) return 0;
    if (r->warm) {
        vrWarm_Sort(&w->warm);
        w->warm.structure = w->structure;
    }
    vrSave_Free(w);
    return 0;
}
