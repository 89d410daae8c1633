/* fuzz_lcm.c — AFL++ harness for LCM message decoding (SPEC 11): each
 * input is played by lcm_replay.h through a worker and the SGP's decoders,
 * as tests/test_wire.c replays the inputs found. */
#include <stdlib.h>
#include "lcm_replay.h"
#include "harness.h"

static void fuzz_one(const unsigned char *data, size_t len)
{
    /* one link for the process: an input leaves it empty, and a new lcm_t
     * per input would cost more than the input itself */
    static vrLink link;
    static int open;
    char err[256];
    if (!open && vrLink_Open(&link, "memq://", VR_LINK_SGP, err, sizeof err) != 0) abort();
    open = 1;
    if (lcm_replay(&link, data, len) != 0) abort();
}
