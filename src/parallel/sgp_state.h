/* sgp_state.h — the SGP's state (thesis 3.5.2, SPEC 5): its workers, the
 * request in flight and the answers, and the frame start kept to redo the
 * frame.  Shared by the SGP's files: exchange.c (a request and its
 * answers), spawn.c (the workers' start and end), setup.c (their objects
 * and pairs) and sgp.c (the owner set). */
#ifndef VROC_SGP_STATE_H
#define VROC_SGP_STATE_H

#include <sys/types.h>
#include "config.h"
#include "world_state.h"
#include "link.h"
#include "worker.h"

#define MAX_OVERLAPS 64

/* what the SGP waits for: the answer names it, so a late one is not taken
 * for the answer to another request */
enum { WAIT_EARLIEST, WAIT_UPDATE, WAIT_CANDIDATES };

/* the rounds by request (stats rounds): frame starts (and start checks),
 * forwarded events, advances, island steps, setups */
enum { ROUND_FRAME, ROUND_FORWARD, ROUND_ADVANCE, ROUND_CONTACTS, ROUND_SETUP, ROUND_KINDS };

/* a worker's owner's counters (stats keys) */
typedef struct vrGpCounts { long long checks, heap_pops, solves, refactors, factors; } vrGpCounts;

typedef struct vrGpInfo {
    long long nonce;
    pid_t pid;                  /* forked workers; 0 otherwise */
    int alive, replied;
    double last_heard;          /* the exchange's idle time (vrSgp.idle_ms) when it last spoke */
    double last_heard_wall;     /* and the clock's (ms) */
    int found;                  /* its last earliest */
    double t;
    long long order;
    int kind;
    double approach;            /* and its n.u and point: what its sound is made of */
    vec3 point;
    vrUpdate answer;            /* its answer to its event, from its earliest (answered) */
    int answered;
    vrGpCounts answer_cost;     /* the KLU counts that answer adds to now's */
    double busy_ms;             /* its time on requests, as it last said */
    int quiet;                  /* its last look-ahead found nothing, nor would an island step */
    int ahead;                  /* its last island step's answer carried the look-ahead after it */
    vrGpCounts now;             /* of its owner, as it last said */
    vrGpCounts before;          /* of the owners it had before: a setup makes a new one */
    int copies, pairs;          /* its objects; its share of the pairs (the deal's count) */
    long long records;          /* of its share, the pairs with a record now (lazy, SPEC 10) */
    vrBuf setup;                /* its setup during a setup round */
} vrGpInfo;

struct vrSgp {
    vrLink link;
    char url[256];
    int n;
    vrGpInfo gp[VR_MAX_GPS];
    vrWorker *local[VR_MAX_GPS];   /* memq://: workers in this process */
    long long run, seq;
    long structure;             /* the world's, at the last setup */
    int waiting, responder, setup_round, max_id;
    int taken;                  /* the worker whose answer the next forward carries, or -1 */
    int quiet;                  /* the last round was a look-ahead to quiet_t and every worker was quiet */
    double quiet_t;
    double owed_t, owed_h;      /* an island step answered without a round (owed_h > 0), for the next request */
    int ahead;                  /* the last island step's round carried the contact step's look-ahead, */
    vrGrid ahead_g;             /* on this grid with this allow_instant, and changed nothing: */
    int ahead_allow;            /* the look-ahead's first round is saved (sgp.c) */
    vrBuf req;                  /* the broadcast request awaiting answers */
    const char *req_channel;
    vrUpdate reply;             /* the responder's states */
    vrTouches touches;          /* an island step: what the workers found */
    int overlap[MAX_OVERLAPS][2], noverlap;
    char error[256];
    int frame_open;
    int frame_fresh;            /* the frame opened with an island step: its frame_start not sent yet */
    int sound_failed;           /* the last frame's sounds could not be published */
    vrUpdate snap, snap_pending;   /* the frame start, to redo the frame */
    vrWarm snap_warm;           /* the island steps' warm start then (structure -1: lost) */
    long long snap_collisions, snap_island_steps, snap_island_contacts, snap_clamps;
    vrGpCounts snap_counts[VR_MAX_GPS];  /* each worker's counts then (before + now) */
    long long requests, received, foreign, malformed;
    double idle_ms;             /* of the current exchange: waits in which no message came */
    long long rounds[ROUND_KINDS];
    double wait_ms;             /* in exchanges: waiting for answers (and in-process workers' work) */
    lcm_subscription_t *subs[4];
};

#endif
