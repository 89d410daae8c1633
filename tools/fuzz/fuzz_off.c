/* fuzz_off.c — AFL++ harness for the OFF reader (SPEC 1.1, 11): an input
 * is an OFF file, read by vrPolyhedron_FromOFF as `file = PATH` reads one
 * (the reader takes a path, so the input is written to input.off in the
 * current folder first: make fuzz runs it inside build/fuzz/off/). */
#include "off.h"
#include "harness.h"

static void fuzz_one(const unsigned char *data, size_t len)
{
    char err[512];
    vrPolyhedron *p = NULL;
    FILE *f = fopen("input.off", "wb");
    if (!f || fwrite(data, 1, len, f) != len || fclose(f) != 0) abort();
    if (vrPolyhedron_FromOFF("input.off", &p, err, sizeof err) == 0) vrPolyhedron_Free(p);
}
