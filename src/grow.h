/* grow.h — how arrays grow here: room for `need` elements of `size` bytes
 * in *arr, whose capacity *cap doubles (from 16) as needed.  Returns -1
 * when memory runs out, *arr and *cap then as they were. */
#ifndef VROC_GROW_H
#define VROC_GROW_H

#include <stdlib.h>

static inline int vrGrow(void **arr, int *cap, int need, size_t size)
{
    int c = *cap ? *cap : 16;
    void *n;
    if (need <= *cap) return 0;
    while (c < need) c *= 2;
    n = realloc(*arr, (size_t)c * size);
    if (!n) return -1;
    *arr = n;
    *cap = c;
    return 0;
}

#endif
