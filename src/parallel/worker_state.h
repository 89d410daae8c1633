/* worker_state.h — a worker's state (thesis 3.5, SPEC 5), shared by its
 * files: worker.c (the requests and the process), worker_reply.c (its
 * answers and heartbeats) and worker_hold.c (the objects and pairs it
 * holds).  As sgp_state.h is the coordinator's. */
#ifndef VROC_WORKER_STATE_H
#define VROC_WORKER_STATE_H

#include <sys/types.h>
#include "owner.h"
#include "table.h"
#include "distribution.h"
#include "worker.h"

#define HELLO_MS 100.0      /* announcements while free, heartbeats while busy */

struct vrWorker {
    vrLink *link;
    long long nonce;
    int forked;
    pid_t parent;
    int64_t run, last_seq, reply_seq;
    int gp;
    vrBuf reply;                  /* the last answer, for repeated requests */
    const char *reply_channel;
    vrTable objects;              /* the objects of its pairs, at the SGP's ids */
    vrOwner *owner;
    vrDeal deal;                  /* which pairs are its own (its owner's filter) */
    int setup_next;               /* the setup part expected next (-1: none before a part 0) */
    int *setup_pending, nsetup_pending, setup_pending_cap;   /* the setup's pending bodies so far */
    vrParams params;
    vrEvent first;                /* the first event it last reported */
    int has_first;
    vrUpdate scratch;
    vrUpdate answer;              /* its answer to `first`, sent with it (answered) */
    int answered;
    int thesis_rounds;            /* VROC_THESIS_ROUNDS=1 */
    int quiet;                    /* the last look-ahead found nothing, nor would an island step (vrOwner_Quiet) */
    vrResponseStats answer_cost;  /* the KLU counts that answer added */
    vrResponseStats wasted;       /* those of answers not taken: not in its statistics */
    double busy_ms, busy_from;    /* time spent on requests; the current one's start */
    int *ids;
    int idcap;
    long frames;
    int kill_gp, kill_frame;      /* VROC_FAULT_KILL=gp:frame[:round] */
    int kill_round, rounds;       /* ...at that frame's round-th event (0: at its start) */
    int silent, done;
    double last_hello;
    lcm_subscription_t *subs[6];
};

#endif
