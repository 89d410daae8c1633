/* world_state.h — the coordinator's state (ARCHITECTURE "the loop, once"):
 * the objects, the settings, the clock, the owners of the pairs and what
 * they have not heard yet.  The shell never sees this: it uses
 * include/vroc.h.  It is a header of its own, apart from world.c (the
 * world's life cycle, which frees the workers), because the floors below
 * that file need this state.
 *
 * The coordinator's files, from the floor up (each calls only what is
 * below it):
 *   config.c table.c build.c    settings and definitions; the object table;
 *                               an object built from its definition
 *   world_state.h ownerset.h    this state; what the coordinator asks of owners
 *   rest.c, parallel/sgp.c      rest (SPEC 3.5); the workers as an owner set
 *   owners.c                    the owner choice and the serial owner set
 *   island_step.c               the contacts of an instant, solved together (SPEC 7)
 *   start.c                     a start: objects go live, owners come to date
 *   grab.c grab_save.c          the hand's select mode (SPEC 8): grab, throw, fly;
 *   hand_filter.c               its save line; the 1-euro filter on the hand
 *   loop.c edit.c query.c       the frame loop; live edits; the getters
 *   world.c random.c output.c   life cycle; `random`; `dump` and `stats`
 */
#ifndef VROC_WORLD_STATE_H
#define VROC_WORLD_STATE_H

#include "vroc.h"
#include "owner.h"
#include "panel.h"
#include "reach.h"
#include "splitmix.h"
#include "table.h"
#include "sound.h"
#include "track.h"
#include "island.h"
#include "warm.h"
#include "grab.h"
#include "instant_undo.h"

typedef struct vrSgp vrSgp;
struct vrResume;

struct vrWorld {
    vrSettings s;
    vrTable table;           /* the objects, by id */
    double t;
    long frames;
    double t_base;           /* frame times are t_base + k time_step, k frames since */
    long frames_base;        /* (summing time_step frame by frame would drift) */
    int started;             /* the pair set exists */
    int instant;             /* responses at instant_t, the last event's time (SPEC 3.1's cap) */
    double instant_t;
    int params_dirty;        /* settings changed (config.h's VR_PARAMS_*): for the next frame */
    long structure;          /* bumped when objects, shapes, masses or settings change */
    vrOwner *owner;          /* serial: one owner of every pair (NULL while workers run) */
    vrSgp *sgp;              /* parallel: the workers (parallel/sgp.h) */
    vrUpdate pending;        /* states changed since the owners last heard */
    vrOwnerStats retired;    /* statistics of owners that are gone */
    int may_rest;            /* resting bodies, or more: 0 means none (rest begins only at
                                frame ends, where they are counted) */
    double frame_pose_t;     /* the last frame end, where lazy frame poses are taken (rest.c) */
    vrBody **dyn;            /* live dynamic bodies, for the grid */
    int ndyn, dyncap;
    int *dyn_slot;           /* by object id below ndyn_slot: its index in dyn, or -1 */
    int ndyn_slot, dyn_slotcap;
    vrReach reach;           /* the grid's largest reach, from bounds on dyn */
    vrUpdate update;
    vrInstantLog instant_log; /* loop.c: an instant's pairwise answers, to take back (instant_undo.h) */
    int *changed;            /* scratch: ids changed by an update */
    int nchanged, changedcap;
    vrTouches touches;       /* scratch: an island step's touching pairs */
    /* loop.c: the grid and allow_instant a contact step's look-ahead will
     * have if its island step changes nothing (valid = 1 during that step,
     * with workers only):
     * the SGP sends them with the step's request (sgp.c, ahead) */
    struct { vrGrid g; int allow, valid; } ahead;
    /* island_step.c: the ids of bodies that may be in a contact step (every
     * one that is, and others; found again from every object when
     * structure is no longer contact_structure), and its scratch by
     * object id, set only where a step uses it */
    int *contact_ids;
    int ncontact_ids, contact_idcap;
    long contact_structure;
    /* loop.c: every dynamic body rested when structure was still_structure
     * and applied still_applied (applied counts the updates applied and
     * the frames undone, vrWorld_ApplyUpdate and vrContactSet_Lost) */
    long long applied, still_applied;
    long still_structure;
    vrIslandScratch solve_scratch;   /* the island solver's arrays (island.h) */
    /* island_step.c's island under solve: its bodies and contacts, kept
     * from step to step (made and freed at each, a pile's island of 500
     * contacts was mapped and unmapped anew, 15 % of a landing) */
    struct vrIslandWork { int n, cap, nc, ccap; int *id; vrIslandBody *body; vrIslandContact *c;
                          unsigned char *pushed; } isl_work;
    int *isl_parent, *isl_in, *isl_slot, *isl_ids;
    int isl_cap;
    vrWarm warm, warm_next;  /* the last island step's impulses (warm.h); the step's being kept */
    /* statistics (SPEC 1.3, 7) */
    long subframes;
    long long collisions;
    long long island_steps;  /* island steps that solved an island */
    long long island_contacts; /* contacts those steps solved */
    long long clamps;        /* velocities the speed caps cut (stats clamps) */
    double frame_ms, sim_ms, render_ms;
    vrSounds sounds;         /* this frame's collision sounds (sound.c, SPEC 8) */
    vrTrack track[2];        /* the head and the hand, by vrDevice (tracker.c, SPEC 8) */
    vrPanel panel;           /* the virtual tool panel (panel.c, SPEC 8) */
    vrGrab grab;             /* what the hand holds, the view it flew (grab.c, SPEC 8) */
    /* `random` */
    int random_next;
    vrSplitmix rng;
    struct vrResume *resume; /* a saved file read, for the next start (save.h) */
};

static inline vrObject *vrWorld_Object(const vrWorld *w, vrObjectId id) { return vrTable_Get(&w->table, id); }

#endif
