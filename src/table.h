/* table.h — the objects by id: their names, definitions, shapes and bodies.
 *
 * The world keeps every object in one table (the shell's names, creation
 * order as ids); a worker keeps the objects of its pairs in one of its own,
 * at the same ids, built by the same code (build.h), so every copy moves
 * the same bits. */
#ifndef VROC_TABLE_H
#define VROC_TABLE_H

#include "vroc.h"
#include "event.h"

typedef struct vrObject {
    char name[VR_NAME_MAX + 1];
    vrObjectDef def;
    int alive;
    int built;               /* shape and mass made from def */
    int live;                /* in the simulation: edits now act on its motion */
    struct vrSharedShape *shape;   /* its hull (a sphere's: its drawing mesh) and drawing mesh, shared
                                      by the objects of one shape (shape_share.h); NULL until built */
    vrPolyhedron *off;       /* OFF file loaded by vrObject_SetDef, waiting to be built */
    char *off_text;          /* that file's text, for workers to build the same polyhedron */
    vrBody body;
    int overlap_owed;        /* added, or moved by an edit, since the last start that
                                checked: its pairs are checked at the next (SPEC 1.4) */
    vrPose frame_pose;       /* at the end of the last frame (SPEC 3.5) */
    int have_frame_pose;
    int frame_pose_lazy;     /* frame_pose not taken yet: the pose at the world's
                                frame_pose_t from the anchor it has (rest.c) */
    int quiet_frames;        /* frames in a row it was still, not speeding up (rest.c) */
    int slow_frames;         /* frames in a row it was slow, not speeding up (rest.c) */
    double slow_start;       /* its motion over the first frame of that window (m) */
    int tipping;             /* at its last island step this frame its supports missed its centre
                              * (balance.h): it may not rest */
    struct vrSavedBody *saved; /* read from a saved file, until it goes live (saved.h) */
} vrObject;

typedef struct vrTable {
    vrObject **obj;          /* by id (creation order); deleted ones stay NULL */
    int n, cap;
    int *index;              /* ids by name hash, open addressing (-1: empty); a deleted
                                object's id lingers until the index is made again */
    int indexcap, nindex;
    int unready;             /* an object may be unbuilt, not live yet, owed an overlap check or
                                holding a saved state: vrWorld_Start's passes over the table
                                have work (start.c; set wherever that begins) */
} vrTable;

vrObject *vrTable_Get(const vrTable *t, int id);
/* the id of the object called name, or VR_NO_OBJECT */
int vrTable_Find(const vrTable *t, const char *name);
/* a new object at id t->n with vrObjectDef_Default(type) */
int vrTable_Add(vrTable *t, const char *name, vrObjectType type, int *id, char *err, size_t n);
/* an object at a given id (a worker holds a subset of the SGP's objects);
 * off_text: the OFF file's text for polyhedra, or NULL */
int vrTable_Put(vrTable *t, int id, const vrObjectDef *def, const char *off_text, char *err, size_t n);
int vrTable_Count(const vrTable *t);
/* the ids in order: up to max in ids, returns how many there are */
int vrTable_List(const vrTable *t, int *ids, int max);
/* frees every object; the table is empty */
void vrTable_Clear(vrTable *t);
void vrTable_Free(vrTable *t);

/* SPEC 3.3: two objects in the simulation make a pair unless both are static */
int vrTable_LivePair(const vrTable *t, int i, int j);
/* by body id (n + 1 bytes, to free; NULL when out of memory): 1 when its
 * state is among pending, or an overlap check is owed, so that a new
 * owner's pair of it is evaluated afresh */
unsigned char *vrTable_PendingMarks(const vrTable *t, const vrUpdate *pending);

/* a new definition of the same type, checked; a polyhedron's new OFF file
 * is read now (its errors are the definition's); *old: the one replaced */
int vrObject_SetDef(vrObject *o, const vrObjectDef *def, vrObjectDef *old, char *err, size_t n);
/* frees the hull and the drawing mesh (they are built again) */
void vrObject_FreeShape(vrObject *o);
void vrObject_Free(vrObject *o);

#endif
