/* link.c — the LCM transport with fault injection for tests. */
#include <stdlib.h>
#include <stdio.h>
#include <string.h>
#include <time.h>
#include <unistd.h>
#include "link.h"

double vrLink_NowMs(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec * 1e3 + (double)ts.tv_nsec * 1e-6;
}

long long vrLink_NewId(void)
{
    double t = vrLink_NowMs();
    unsigned long long r = (unsigned long long)getpid() << 32 ^ (unsigned long long)(t * 1e3);
    r = (r ^ (r >> 31)) * 0x9e3779b97f4a7c15ULL;
    return (long long)(r >> 2) | 1;      /* positive and never 0 (0 means free) */
}

static double percent_env(const char *name)
{
    const char *v = getenv(name);
    double p = v ? atof(v) : 0; /* NOLINT(cert-err34-c): a test's fault knob; junk reads as 0, no faults */
    return p > 0 ? (p < 100 ? p / 100 : 1) : 0;
}

/* udpm://GROUP[:PORT][?OPTIONS] with PORT + 1 (LCM's default port 7667) */
int vrLink_AnswerUrl(const char *url, char *out, size_t n)
{
    const char *host, *colon, *rest;
    long port = 7667;
    char *end;
    int w;
    if (strncmp(url, "udpm://", 7) != 0) return -1;
    host = url + 7;
    rest = host + strcspn(host, "?");
    colon = memchr(host, ':', (size_t)(rest - host));
    if (colon) {
        port = strtol(colon + 1, &end, 10);
        if (end != rest || colon + 1 == end) return -1;
    } else {
        colon = rest;
    }
    if (port < 1 || port >= 65535) return -1;
    w = snprintf(out, n, "%.*s:%ld%s", (int)(colon - url), url, port + 1, rest);
    return w > 0 && (size_t)w < n ? 0 : -1;
}

static int open_failed(vrLink *l, const char *url, char *err, size_t n)
{
    snprintf(err, n, "cannot open LCM at '%s' (udpm needs a multicast route: as root, "
                     "ip route add 224.0.0.0/4 dev lo; or lcm_url = memq:// runs the workers "
                     "in this process)", url);
    vrLink_Close(l);
    return -1;
}

int vrLink_Open(vrLink *l, const char *url, int side, char *err, size_t n)
{
    char answers[512];
    int split = vrLink_AnswerUrl(url, answers, sizeof answers) == 0;
    l->drop = percent_env("VROC_FAULT_DROP");
    l->dup = percent_env("VROC_FAULT_DUP");
    l->rng = (unsigned long long)getpid() * 0x9e3779b97f4a7c15ULL + 1;
    l->sent = l->dropped = 0;
    l->lcm = lcm_create(split && side == VR_LINK_SGP ? answers : url);
    l->out = !split ? l->lcm : lcm_create(side == VR_LINK_SGP ? url : answers);
    if (!l->lcm || !l->out) return open_failed(l, url, err, n);
    return 0;
}

void vrLink_Close(vrLink *l)
{
    if (l->out && l->out != l->lcm) lcm_destroy(l->out);
    if (l->lcm) lcm_destroy(l->lcm);
    l->lcm = l->out = NULL;
}

static double chance(vrLink *l)
{
    l->rng = l->rng * 6364136223846793005ULL + 1442695040888963407ULL;
    return (double)(l->rng >> 11) / 9007199254740992.0;
}

int vrLink_Publish(vrLink *l, const char *channel, const void *data, int len)
{
    int copies = 1, i, r = 0;
    if (l->drop > 0 && chance(l) < l->drop) {
        l->dropped++;
        return 0;
    }
    if (l->dup > 0 && chance(l) < l->dup) copies = 2;
    for (i = 0; i < copies; i++) {
        r |= lcm_publish(l->out, channel, data, (unsigned)len);
        l->sent++;
    }
    return r;
}

int vrLink_Handle(vrLink *l, int ms) { return lcm_handle_timeout(l->lcm, ms); }

int vrBuf_Reserve(vrBuf *b, int size)
{
    if (size < 0) return -1;
    if (size > b->cap) {
        void *d = realloc(b->data, (size_t)size);
        if (!d) return -1;
        b->data = d;
        b->cap = size;
    }
    return 0;
}

void vrBuf_Free(vrBuf *b)
{
    free(b->data);
    b->data = NULL;
    b->len = b->cap = 0;
}
