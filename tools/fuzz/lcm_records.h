/* lcm_records.h — the record kinds of fuzz_lcm.c's inputs, shared with
 * lcm_seeds.c that writes its first corpus.  A kind with a channel goes to
 * the worker on it; one without is the SGP's to decode. */
#ifndef VROC_FUZZ_LCM_RECORDS_H
#define VROC_FUZZ_LCM_RECORDS_H

#include "parallel/link.h"

enum {
    REC_SETUP, REC_FRAME, REC_ADVANCE, REC_FORWARD, REC_CONTACTS, REC_SHUTDOWN,
    REC_HELLO, REC_EARLIEST, REC_UPDATE, REC_CANDIDATES, REC_KINDS
};

static const char *const rec_channel[REC_KINDS] = {
    VR_CH_SETUP, VR_CH_FRAME, VR_CH_ADVANCE, VR_CH_FORWARD, VR_CH_CONTACTS, VR_CH_SHUTDOWN,
    NULL, NULL, NULL, NULL
};

#endif
