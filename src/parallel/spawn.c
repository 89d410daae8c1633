/* spawn.c — the workers of an SGP: forked, claimed, or in this process.
 *
 * A forked worker gets a nonce (from the run id) to announce itself with;
 * a hand-started one (`vroc-gp URL`, for a ttl >= 1 URL) announces a nonce
 * of its own and is claimed by the first SGP that hears it (exchange.c's
 * take_hello).  The SGP waits ANNOUNCE_MS for all of them.
 *
 *   local_url / remote_url  memq:// (in this process) and ttl >= 1 (by hand)
 *   fork_workers            one process per worker, running vrWorker_Main
 *   await_workers           until every worker announced itself
 */
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>
#include "exchange.h"
#include "spawn.h"
#include "vroc_shutdown_t.h"

#define ANNOUNCE_MS 10000.0     /* workers have this long to announce themselves */

static int local_url(const char *url) { return strncmp(url, "memq://", 7) == 0; }

/* ttl >= 1: workers on other hosts, started by hand with vroc-gp URL */
static int remote_url(const char *url)
{
    const char *t = strstr(url, "ttl=");
    return t && atoi(t + 4) >= 1; /* NOLINT(cert-err34-c): LCM parses the URL itself; junk reads as 0, local */
}

static int fork_workers(vrSgp *s, char *err, size_t n)
{
    int i;
    fflush(NULL);                        /* the children must not repeat our buffered output */
    for (i = 0; i < s->n; i++) {
        pid_t pid;
        s->gp[i].nonce = s->run ^ ((long long)(i + 1) << 40);
        pid = fork();
        if (pid < 0) return snprintf(err, n, "cannot fork worker %d", i), -1;
        if (pid == 0) {
            char e[256];
            _exit(vrWorker_Main(s->url, s->gp[i].nonce, 1, e, sizeof e) == 0 ? 0 : 1);
        }
        s->gp[i].pid = pid;
    }
    return 0;
}

static int await_workers(vrSgp *s, char *err, size_t n)
{
    double start = vrLink_NowMs();
    while (vrSgp_AliveCount(s) < s->n) {
        if (vrLink_NowMs() - start > ANNOUNCE_MS)
            return snprintf(err, n, "only %d of %d workers announced themselves on %s", vrSgp_AliveCount(s), s->n, s->url), -1;
        vrLink_Handle(&s->link, 20);
    }
    return 0;
}

vrSgp *vrSgp_Open(const vrSettings *st, char *err, size_t n)
{
    vrSgp *s = calloc(1, sizeof *s);
    int i;
    if (!s) return snprintf(err, n, "out of memory"), NULL;
    snprintf(s->url, sizeof s->url, "%s", st->lcm_url);
    s->n = st->gps;
    s->run = vrLink_NewId();
    s->structure = -1;
    s->responder = -1;
    vrUpdate_Init(&s->reply);
    vrUpdate_Init(&s->snap);
    vrUpdate_Init(&s->snap_pending);
    if (!local_url(s->url) && !remote_url(s->url) && fork_workers(s, err, n) != 0) {
        vrSgp_Free(s);
        return NULL;
    }
    if (vrLink_Open(&s->link, s->url, VR_LINK_SGP, err, n) != 0) {
        vrSgp_Free(s);
        return NULL;
    }
    vrSgp_Subscribe(s);
    for (i = 0; local_url(s->url) && i < s->n; i++) {
        s->gp[i].nonce = s->run ^ ((long long)(i + 1) << 40);
        s->local[i] = vrWorker_Create(&s->link, s->gp[i].nonce, 0);
        s->gp[i].alive = s->local[i] != NULL;
    }
    if (await_workers(s, err, n) != 0) {
        vrSgp_Free(s);
        return NULL;
    }
    return s;
}

void vrSgp_Free(vrSgp *s)
{
    vroc_shutdown_t m;
    vrBuf b = {NULL, 0, 0};
    int i, k;
    if (!s) return;
    if (s->link.lcm) {
        m.run = s->run;
        m.seq = ++s->seq;
        if (VR_ENCODE(&b, vroc_shutdown_t, &m) == 0)
            for (k = 0; k < 3; k++) vrLink_Publish(&s->link, VR_CH_SHUTDOWN, b.data, b.len);
        vrBuf_Free(&b);
    }
    for (i = 0; i < s->n; i++) {
        double start = vrLink_NowMs();
        struct timespec pause = {0, 2000000};
        int status;
        vrWorker_Free(s->local[i]);
        while (s->gp[i].pid > 0 && waitpid(s->gp[i].pid, &status, WNOHANG) == 0) {
            if (vrLink_NowMs() - start > 1000) {
                kill(s->gp[i].pid, SIGKILL);
                waitpid(s->gp[i].pid, &status, 0);
                break;
            }
            nanosleep(&pause, NULL);
        }
        vrBuf_Free(&s->gp[i].setup);
        vrUpdate_Free(&s->gp[i].answer);
    }
    vrSgp_Unsubscribe(s);
    vrLink_Close(&s->link);
    vrBuf_Free(&s->req);
    vrUpdate_Free(&s->reply);
    vrTouches_Free(&s->touches);
    vrUpdate_Free(&s->snap);
    vrUpdate_Free(&s->snap_pending);
    vrWarm_Free(&s->snap_warm);
    free(s);
}
