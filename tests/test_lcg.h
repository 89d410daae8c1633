/* test_lcg.h — random numbers for tests: a 64-bit LCG (Knuth's MMIX
 * constants) seeded by TEST_LCG_SEED, defined before the include, so each
 * test file draws its own cases, the same on every run. */
#ifndef VROC_TEST_LCG_H
#define VROC_TEST_LCG_H

#include "vec.h"

#ifndef TEST_LCG_SEED
#error "define TEST_LCG_SEED before including test_lcg.h"
#endif

static unsigned long long rng = TEST_LCG_SEED;
static inline double uni(void) /* [0, 1) */
{
    rng = rng * 6364136223846793005ULL + 1442695040888963407ULL;
    return (double)(rng >> 11) / 9007199254740992.0;
}
static inline double sym(double r) { return (2 * uni() - 1) * r; }
static inline vec3 rvec(double r) { return vec3_make(sym(r), sym(r), sym(r)); }

#endif
