/* heap.c — binary min-heap with positions, so a pair's key can move in
 * O(log p) when an event changes its objects (thesis 3.3.1.2). */
#include <stdlib.h>
#include "grow.h"
#include "heap.h"

static int before(const vrHeapEntry *a, const vrHeapEntry *b)
{
    return a->key < b->key || (a->key == b->key && a->order < b->order);
}

static void place(vrHeap *h, int i, vrHeapEntry e)
{
    h->e[i] = e;
    h->pos[e.id] = i;
}

static void sift_up(vrHeap *h, int i)
{
    vrHeapEntry e = h->e[i];
    while (i > 0) {
        int parent = (i - 1) / 2;
        if (!before(&e, &h->e[parent])) break;
        place(h, i, h->e[parent]);
        i = parent;
    }
    place(h, i, e);
}

static void sift_down(vrHeap *h, int i)
{
    vrHeapEntry e = h->e[i];
    for (;;) {
        int c = 2 * i + 1;
        if (c >= h->n) break;
        if (c + 1 < h->n && before(&h->e[c + 1], &h->e[c])) c++;
        if (!before(&h->e[c], &e)) break;
        place(h, i, h->e[c]);
        i = c;
    }
    place(h, i, e);
}

void vrHeap_Init(vrHeap *h)
{
    h->e = NULL;
    h->pos = NULL;
    h->n = h->cap = h->idcap = 0;
}

void vrHeap_Free(vrHeap *h)
{
    free(h->e);
    free(h->pos);
    vrHeap_Init(h);
}

static int reserve(vrHeap *h, int id)
{
    int i, old = h->idcap;
    if (vrGrow((void **)&h->pos, &h->idcap, id + 1, sizeof *h->pos) != 0) return -1;
    for (i = old; i < h->idcap; i++) h->pos[i] = -1;
    return vrGrow((void **)&h->e, &h->cap, h->n + 1, sizeof *h->e);
}

int vrHeap_Set(vrHeap *h, int id, double key, long long order)
{
    vrHeapEntry e;
    int i;
    if (reserve(h, id) != 0) return -1;
    e.key = key;
    e.order = order;
    e.id = id;
    i = h->pos[id];
    if (i < 0) {
        place(h, h->n++, e);
        sift_up(h, h->n - 1);
    } else {
        int up = before(&e, &h->e[i]);
        place(h, i, e);
        if (up) sift_up(h, i); else sift_down(h, i);
    }
    return 0;
}

void vrHeap_Remove(vrHeap *h, int id)
{
    int i = id < h->idcap ? h->pos[id] : -1;
    vrHeapEntry last;
    if (i < 0) return;
    h->pos[id] = -1;
    last = h->e[--h->n];
    if (i == h->n) return;
    place(h, i, last);
    sift_up(h, i);
    sift_down(h, h->pos[last.id]);
}

int vrHeap_Contains(const vrHeap *h, int id) { return id < h->idcap && h->pos[id] >= 0; }

int vrHeap_Top(const vrHeap *h, double *key)
{
    if (h->n == 0) return -1;
    if (key) *key = h->e[0].key;
    return h->e[0].id;
}

int vrHeap_Pop(vrHeap *h)
{
    int id = vrHeap_Top(h, NULL);
    if (id >= 0) vrHeap_Remove(h, id);
    return id;
}

double vrHeap_Key(const vrHeap *h, int id) { return h->e[h->pos[id]].key; }
