/* splitmix.h — the seeded stream `random` draws from (SPEC 1.2):
 * splitmix64 (Steele, Lea, Flood 2014), so that a seed always gives the
 * same scene. */
#ifndef VROC_SPLITMIX_H
#define VROC_SPLITMIX_H

#include <stdint.h>

typedef struct vrSplitmix { unsigned long long state; } vrSplitmix;

static inline void vrSplitmix_Seed(vrSplitmix *r, unsigned long long seed) { r->state = seed; }

static inline uint64_t vrSplitmix_Next(vrSplitmix *r)
{
    uint64_t z = (r->state += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
}

/* uniform in [0, 1), 53 bits */
static inline double vrSplitmix_Uniform(vrSplitmix *r)
{
    return (double)(vrSplitmix_Next(r) >> 11) * (1.0 / 9007199254740992.0);
}

#endif
