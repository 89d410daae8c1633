/* link.h — LCM as the transport between the SGP and its workers (SPEC 5).
 *
 * Over UDP multicast the two directions are two groups' ports: requests
 * go on the URL's port, answers on the port after it.  Every socket on a
 * port is woken by every datagram sent to it, so on one port each worker
 * woke for the other workers' answers and the SGP for its own requests
 * (9 wake-ups a round with 2 workers, 4 now).  memq:// and other
 * providers keep one instance for both.
 *
 * Messages are LCM types (the .lcm files beside this one, C code generated at build
 * time).  Receivers subscribe raw and decode themselves, so that a
 * malformed message is counted and dropped instead of printed.  For tests,
 * VROC_FAULT_DROP and VROC_FAULT_DUP (percent) make the link lose or repeat
 * outgoing messages.
 */
#ifndef VROC_LINK_H
#define VROC_LINK_H

#include <stddef.h>
#include <string.h>
#include <lcm/lcm.h>

typedef struct vrLink {
    lcm_t *lcm;                        /* what this side receives (and, with one instance, sends) */
    lcm_t *out;                        /* what it sends on: lcm, or the other direction's port */
    double drop, dup;                  /* fault injection, probabilities */
    unsigned long long rng;
    long long sent, dropped;
} vrLink;

/* which direction a side listens to */
enum { VR_LINK_SGP, VR_LINK_WORKER };
int vrLink_Open(vrLink *l, const char *url, int side, char *err, size_t n);
/* the URL answers travel on (udpm://: the port after url's), in out[0..n);
 * 0, or -1 when url has one channel for both directions */
int vrLink_AnswerUrl(const char *url, char *out, size_t n);
void vrLink_Close(vrLink *l);
int vrLink_Publish(vrLink *l, const char *channel, const void *data, int len);
/* waits up to ms for messages and dispatches them to the subscribers */
int vrLink_Handle(vrLink *l, int ms);
double vrLink_NowMs(void);
/* an id for a run or a worker, from the process id and the clock: positive, never 0 */
long long vrLink_NewId(void);

/* an encoded message kept for sending (and resending) */
typedef struct vrBuf { void *data; int len, cap; } vrBuf;
int vrBuf_Reserve(vrBuf *b, int size);
void vrBuf_Free(vrBuf *b);

/* encodes an LCM message of generated type T into buffer b; 0 on success */
#define VR_ENCODE(b, T, msg)                                                             \
    (vrBuf_Reserve((b), T##_encoded_size(msg)) != 0 ? -1                                 \
     : ((b)->len = T##_encode((b)->data, 0, (b)->cap, (msg))) < 0 ? -1 : 0)

/* Defines `static void name(...)`, an LCM subscriber for messages of the
 * generated type T whose user data is a Ctx *: the message is decoded,
 * given to take(ctx, &msg) and freed; one that does not decode goes to
 * malformed(ctx) instead, after what its decoding allocated is freed (the
 * message starts zeroed, and tools/lcm-guard.sed makes the decoders leave
 * only what cleanup can free).  (Receivers subscribe raw: see above.) */
#define VR_HANDLER(name, T, Ctx, take, malformed)                                        \
    static void name(const lcm_recv_buf_t *rb, const char *channel, void *user)          \
    {                                                                                    \
        T msg;                                                                           \
        (void)channel;                                                                   \
        memset(&msg, 0, sizeof msg);                                                     \
        if (T##_decode(rb->data, 0, (int)rb->data_size, &msg) < 0) {                     \
            T##_decode_cleanup(&msg);                                                    \
            malformed((Ctx *)user);                                                      \
            return;                                                                      \
        }                                                                                \
        take((Ctx *)user, &msg);                                                         \
        T##_decode_cleanup(&msg);                                                        \
    }

#define VR_CH_HELLO "VROC_HELLO"
#define VR_CH_SETUP "VROC_SETUP"
#define VR_CH_FRAME "VROC_FRAME"
#define VR_CH_EARLIEST "VROC_EARLIEST"
#define VR_CH_ADVANCE "VROC_ADVANCE"
#define VR_CH_UPDATE "VROC_UPDATE"
#define VR_CH_FORWARD "VROC_FORWARD"
#define VR_CH_SHUTDOWN "VROC_SHUTDOWN"
#define VR_CH_CONTACTS "VROC_CONTACTS"
#define VR_CH_CANDIDATES "VROC_CANDIDATES"

#endif
