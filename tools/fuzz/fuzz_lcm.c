/* fuzz_lcm.c — AFL++ harness for LCM message decoding (SPEC 11).
 *
 * An input is a run of records, each [kind][length: 2 bytes, big-endian]
 * [that many bytes], read as the message kind names (lcm_records.h).  The
 * worker's six kinds are published on an in-process memq:// link to a real
 * worker (nonce 1), which decodes, validates and acts on them as a GP does
 * (setup builds its objects, frame_start looks ahead ...); the SGP's kinds
 * (hello, earliest, candidates, update) are decoded and passed through
 * the wire checks the SGP applies.  A message must never crash either side.
 */
#include <string.h>
#include "link.h"
#include "worker.h"
#include "wire.h"
#include "vroc_earliest_t.h"
#include "vroc_hello_t.h"
#include "vroc_update_t.h"
#include "lcm_records.h"
#include "harness.h"

/* decodes as VR_HANDLER does (link.h): zeroed first, cleaned up either way */
#define DECODE(T, p, len, msg) \
    (memset(&(msg), 0, sizeof(msg)), T##_decode((p), 0, (len), &(msg)) >= 0 ? 1 : (T##_decode_cleanup(&(msg)), 0))

/* the SGP's side: decode, then the checks its handlers make */
static void sgp_side(int kind, const unsigned char *p, int len)
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
    if (kind == REC_HELLO && DECODE(vroc_hello_t, p, len, h)) vroc_hello_t_decode_cleanup(&h);
    if (kind == REC_EARLIEST && DECODE(vroc_earliest_t, p, len, e)) {
        vrWire_GetStates(e.states, e.nstates, 64, &up);   /* the answer it carries */
        vroc_earliest_t_decode_cleanup(&e);
    }
    if (kind == REC_UPDATE && DECODE(vroc_update_t, p, len, u)) {
        vrWire_GetStates(u.states, u.nstates, 64, &up);
        vrWire_GetGrid(&u.grid, &grid);
        vroc_update_t_decode_cleanup(&u);
    }
    if (kind == REC_CANDIDATES && DECODE(vroc_candidates_t, p, len, c)) {
        vrWire_GetTouches(&c, 64, &touches);
        vroc_candidates_t_decode_cleanup(&c);
    }
    vrTouches_Free(&touches);
    vrUpdate_Free(&up);
}

static void fuzz_one(const unsigned char *data, size_t len)
{
    /* one link for the process: an input leaves it empty (every message is
     * handled before the next record), and a new lcm_t per input would cost
     * more than the input itself */
    static vrLink link;
    static int open;
    char err[256];
    vrWorker *k;
    size_t at = 0;
    if (!open && vrLink_Open(&link, "memq://", err, sizeof err) != 0) abort();
    open = 1;
    k = vrWorker_Create(&link, 1, 0);
    if (!k) abort();
    while (at + 3 <= len) {
        int kind = data[at] % REC_KINDS, n = data[at + 1] << 8 | data[at + 2];
        if ((size_t)n > len - at - 3) n = (int)(len - at - 3);
        at += 3;
        if (rec_channel[kind]) {
            lcm_publish(link.lcm, rec_channel[kind], data + at, n);
            while (vrLink_Handle(&link, 0) > 0) continue;   /* its answers too: nobody takes them */
        } else {
            sgp_side(kind, data + at, n);
        }
        at += (size_t)n;
    }
    vrWorker_Free(k);
}
