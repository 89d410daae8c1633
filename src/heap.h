/* heap.h — the collision heap (thesis 3.3.1.2): a binary min-heap of pairs
 * keyed by their expected earliest event time, ties broken by pair order so
 * that pops come out in the same order in every process. */
#ifndef VROC_HEAP_H
#define VROC_HEAP_H

typedef struct vrHeapEntry { double key; long long order; int id; } vrHeapEntry;

typedef struct vrHeap {
    vrHeapEntry *e;   /* the heap array */
    int *pos;         /* pos[id]: index in e, or -1 */
    int n, cap, idcap;
} vrHeap;

void vrHeap_Init(vrHeap *h);
void vrHeap_Free(vrHeap *h);
/* inserts id or moves it to its new key; returns -1 on no memory */
int vrHeap_Set(vrHeap *h, int id, double key, long long order);
void vrHeap_Remove(vrHeap *h, int id);
int vrHeap_Contains(const vrHeap *h, int id);
/* the top id (-1 if empty) and its key */
int vrHeap_Top(const vrHeap *h, double *key);
int vrHeap_Pop(vrHeap *h);
/* the key id sits under (only when contained) */
double vrHeap_Key(const vrHeap *h, int id);

#endif
