/* lcm_replay.h — one input of the LCM harness, played (SPEC 11): shared by
 * fuzz_lcm.c, which AFL++ drives, and tests/test_wire.c, which replays the
 * inputs it found, so that a replay runs exactly what crashed the fuzzer.
 *
 * An input is a run of records, each [kind][length: 2 bytes, big-endian]
 * [that many bytes], read as the message kind names (lcm_records.h).  The
 * worker's six kinds are published on an in-process memq:// link to a real
 * worker (nonce 1), which decodes, validates and acts on them as a GP does
 * (setup builds its objects, frame_start looks ahead ...); the SGP's kinds
 * (hello, earliest, candidates, update) are decoded and passed through
 * the wire checks the SGP applies.  A message must never crash either side.
 */
#ifndef VROC_FUZZ_LCM_REPLAY_H
#define VROC_FUZZ_LCM_REPLAY_H

#include <string.h>
#include "parallel/link.h"
#include "parallel/worker.h"
#include "parallel/wire.h"
#include "vroc_earliest_t.h"
#include "vroc_hello_t.h"
#include "vroc_update_t.h"
#include "lcm_records.h"

/* decodes as VR_HANDLER does (link.h): zeroed first, cleaned up either way */
#define LCM_REPLAY_DECODE(T, p, len, msg) \
    (memset(&(msg), 0, sizeof(msg)), T##_decode((p), 0, (len), &(msg)) >= 0 ? 1 : (T##_decode_cleanup(&(msg)), 0))

/* the SGP's side: decode, then the checks its handlers make */
static void lcm_replay_sgp_side(int kind, const unsigned char *p, int len)
{
    vrUpdate up;
    vrTouches touches;
    vrGrid grid;
    vroc_hello_t h;
    vroc_earliest_t e;
    vroc_update_t u;
    vroc_candidates_t c;
    vrUpdate_Init(&up);
    memset(&touches, 0, sizeof touches);
    if (kind == REC_HELLO && LCM_REPLAY_DECODE(vroc_hello_t, p, len, h)) vroc_hello_t_decode_cleanup(&h);
    if (kind == REC_EARLIEST && LCM_REPLAY_DECODE(vroc_earliest_t, p, len, e)) {
        vrWire_GetStates(e.states, e.nstates, 64, &up);   /* the answer it carries */
        vroc_earliest_t_decode_cleanup(&e);
    }
    if (kind == REC_UPDATE && LCM_REPLAY_DECODE(vroc_update_t, p, len, u)) {
        vrWire_GetStates(u.states, u.nstates, 64, &up);
        vrWire_GetGrid(&u.grid, &grid);
        vroc_update_t_decode_cleanup(&u);
    }
    if (kind == REC_CANDIDATES && LCM_REPLAY_DECODE(vroc_candidates_t, p, len, c)) {
        vrWire_GetTouches(&c, 64, &touches);
        vroc_candidates_t_decode_cleanup(&c);
    }
    vrTouches_Free(&touches);
    vrUpdate_Free(&up);
}

/* plays data[0..len) through a new worker on link (left empty after: every
 * message is handled before the next record); -1 if no worker could be made */
static int lcm_replay(vrLink *link, const unsigned char *data, size_t len)
{
    vrWorker *k = vrWorker_Create(link, 1, 0);
    size_t at = 0;
    if (!k) return -1;
    while (at + 3 <= len) {
        int kind = data[at] % REC_KINDS, n = data[at + 1] << 8 | data[at + 2];
        if ((size_t)n > len - at - 3) n = (int)(len - at - 3);
        at += 3;
        if (rec_channel[kind]) {
            lcm_publish(link->lcm, rec_channel[kind], data + at, n);
            while (vrLink_Handle(link, 0) > 0) continue;   /* its answers too: nobody takes them */
        } else {
            lcm_replay_sgp_side(kind, data + at, n);
        }
        at += (size_t)n;
    }
    vrWorker_Free(k);
    return 0;
}

#endif
