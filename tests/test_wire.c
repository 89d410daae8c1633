/* test_wire.c — malformed LCM messages are refused, never trusted (SPEC 5,
 * 11): the decoders lcm-gen writes, as tools/lcm-guard.sed patches them,
 * refuse array counts and strings that do not fit the message, and the
 * messages make fuzz found crashing a worker (tests/data/fuzz_lcm/, each
 * records [kind][length: 2 bytes][message] as tools/fuzz/fuzz_lcm.c reads
 * them) go through a worker over memq:// without harm.  Run under ASan,
 * as make check runs every suite, an overflow or a leak fails it. */
#include <dirent.h>
#include <stdlib.h>
#include "test.h"
#include "parallel/link.h"
#include "parallel/worker.h"
#include "vroc_earliest_t.h"
#include "vroc_frame_start_t.h"
#include "parallel/wire.h"
#include "../tools/fuzz/lcm_replay.h"

#define FRAME_NSTATES_AT 90   /* hash, run, seq, t (8 each), grid (56), two int8 */
/* hash ... noverlap (110 bytes: approach and point are 32, records 8), with
 * noverlap = 0, then the answer's fields (62 bytes with nstates = 0) */
#define EARLIEST_STRING_AT 172

static void put_be32(unsigned char *b, unsigned v)
{
    b[0] = (unsigned char)(v >> 24), b[1] = (unsigned char)(v >> 16), b[2] = (unsigned char)(v >> 8), b[3] = (unsigned char)v;
}

static int frame_decodes(unsigned char *buf, int len)
{
    vroc_frame_start_t m;
    int r;
    memset(&m, 0, sizeof m);
    r = vroc_frame_start_t_decode(buf, 0, len, &m);
    vroc_frame_start_t_decode_cleanup(&m);
    return r >= 0;
}

/* nstates = 2^30 + 1: 4 * count overflowed LCM's size check, and the
 * decoder read that many states past the end of a 100-byte message */
static int test_array_counts_past_the_message_are_refused(void)
{
    static const unsigned counts[] = {0x40000001u, 0x7fffffffu, 0xffffffffu, 0x80000000u, 2};
    unsigned char buf[512];
    vroc_frame_start_t m;
    int len, i;
    memset(&m, 0, sizeof m);
    m.run = 1, m.seq = 2, m.grid.T = 0.1, m.grid.frame_T = 0.1;
    len = vroc_frame_start_t_encode(buf, 0, sizeof buf, &m);
    ENSURE(len > FRAME_NSTATES_AT + 4);
    ENSURE(frame_decodes(buf, len));
    for (i = 0; i < (int)(sizeof counts / sizeof counts[0]); i++) {
        put_be32(buf + FRAME_NSTATES_AT, counts[i]);
        ENSURE_MSG(!frame_decodes(buf, len), "nstates %#x accepted in a %d-byte message", counts[i], len);
    }
    return 0;
}

static int earliest_decodes(unsigned char *buf, int len)
{
    vroc_earliest_t m;
    int r;
    memset(&m, 0, sizeof m);
    r = vroc_earliest_t_decode(buf, 0, len, &m);
    vroc_earliest_t_decode_cleanup(&m);
    return r >= 0;
}

/* a string's length is trusted by lcm_coretypes.h (negative: a huge
 * malloc), and its closing NUL is not checked (strlen then reads on) */
static int test_strings_that_do_not_fit_or_end_are_refused(void)
{
    unsigned char buf[256];
    vroc_earliest_t m;
    int len;
    memset(&m, 0, sizeof m);
    m.error = "abc";
    len = vroc_earliest_t_encode(buf, 0, sizeof buf, &m);
    ENSURE(len == EARLIEST_STRING_AT + 4 + 4);
    ENSURE(earliest_decodes(buf, len));
    buf[len - 1] = 'd';                                  /* no NUL */
    ENSURE(!earliest_decodes(buf, len));
    buf[len - 1] = 0;
    put_be32(buf + EARLIEST_STRING_AT, 0xfffffff0u);     /* negative */
    ENSURE(!earliest_decodes(buf, len));
    put_be32(buf + EARLIEST_STRING_AT, 5);               /* past the end */
    ENSURE(!earliest_decodes(buf, len));
    put_be32(buf + EARLIEST_STRING_AT, 0);               /* not even the NUL */
    ENSURE(!earliest_decodes(buf, len));
    return 0;
}

/* a file's input, played as the fuzzer played it (lcm_replay.h) */
static int replay(vrLink *link, const char *path)
{
    static unsigned char data[1 << 16];
    size_t len;
    FILE *f = fopen(path, "rb");
    if (!f) return -1;
    len = fread(data, 1, sizeof data, f);
    fclose(f);
    return lcm_replay(link, data, len);
}

/* the 54 crashes and 15 hangs make fuzz found (crash-*, hang-*): each
 * replayed through a worker ends, under ASan, without harm */
static int test_messages_the_fuzzer_crashed_a_worker_with_are_dropped(void)
{
    char err[256], path[512];
    vrLink link;
    DIR *d = opendir("tests/data/fuzz_lcm");
    struct dirent *e;
    int n = 0;
    ENSURE_MSG(d, "no tests/data/fuzz_lcm (run from the repository root)");
    ENSURE(vrLink_Open(&link, "memq://", VR_LINK_SGP, err, sizeof err) == 0);
    while ((e = readdir(d)) != NULL) {
        if (strncmp(e->d_name, "crash-", 6) != 0 && strncmp(e->d_name, "hang-", 5) != 0) continue;
        snprintf(path, sizeof path, "tests/data/fuzz_lcm/%s", e->d_name);
        ENSURE_MSG(replay(&link, path) == 0, "%s", path);
        n++;
    }
    closedir(d);
    vrLink_Close(&link);
    ENSURE_MSG(n >= 69, "only %d inputs in tests/data/fuzz_lcm", n);
    return 0;
}

/* answers travel on the port after the requests' (link.h), whatever the
 * URL's options; a URL without a port has LCM's 7667; memq:// and
 * malformed ports keep one channel */
static int test_answers_go_on_the_next_port(void)
{
    char out[128];
    ENSURE(vrLink_AnswerUrl("udpm://239.255.76.67:7667?ttl=0&recv_buf_size=4194304", out, sizeof out) == 0);
    ENSURE_MSG(strcmp(out, "udpm://239.255.76.67:7668?ttl=0&recv_buf_size=4194304") == 0, "%s", out);
    ENSURE(vrLink_AnswerUrl("udpm://239.255.76.67", out, sizeof out) == 0);
    ENSURE_MSG(strcmp(out, "udpm://239.255.76.67:7668") == 0, "%s", out);
    ENSURE(vrLink_AnswerUrl("udpm://239.1.2.3:9000?ttl=1", out, sizeof out) == 0);
    ENSURE_MSG(strcmp(out, "udpm://239.1.2.3:9001?ttl=1") == 0, "%s", out);
    ENSURE(vrLink_AnswerUrl("memq://", out, sizeof out) != 0);
    ENSURE(vrLink_AnswerUrl("udpm://239.1.2.3:x?ttl=1", out, sizeof out) != 0);
    ENSURE(vrLink_AnswerUrl("udpm://239.1.2.3:65535", out, sizeof out) != 0);
    ENSURE(vrLink_AnswerUrl("udpm://239.1.2.3:7667", out, 10) != 0);
    return 0;
}

/* a frame_start whose grid has more steps than any frame may take: the
 * hang make fuzz found (a worker looking ahead over 10^18 grid points) */
static int test_grids_past_a_frames_steps_are_refused(void)
{
    vroc_grid_t m;
    vrGrid g;
    memset(&m, 0, sizeof m);
    m.t0 = 0, m.T = 0.01, m.frame_T = 0.01, m.n = (int64_t)VR_FRAME_STEPS_HARD_MAX, m.h = m.T / (double)m.n;
    ENSURE(vrWire_GetGrid(&m, &g) == 0 && g.n == m.n);
    m.n = m.n + 1;
    ENSURE(vrWire_GetGrid(&m, &g) != 0);
    m.n = (int64_t)1 << 60;
    ENSURE(vrWire_GetGrid(&m, &g) != 0);
    return 0;
}

static const vrTest tests[] = {
    TEST(test_answers_go_on_the_next_port),
    TEST(test_grids_past_a_frames_steps_are_refused),
    TEST(test_array_counts_past_the_message_are_refused),
    TEST(test_strings_that_do_not_fit_or_end_are_refused),
    TEST(test_messages_the_fuzzer_crashed_a_worker_with_are_dropped),
};

const vrTestSuite vrSuite_Wire = {"wire", tests, TEST_COUNT(tests), NULL, NULL, 0};
