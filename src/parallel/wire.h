/* wire.h — the library's structures to and from their LCM messages, with
 * the validation every received message gets before use (sizes, ranges,
 * finite numbers): a malformed message is dropped, never trusted. */
#ifndef VROC_WIRE_H
#define VROC_WIRE_H

#include "vroc.h"
#include "owner.h"
#include "vroc_body_def_t.h"
#include "vroc_body_state_t.h"
#include "vroc_grid_t.h"
#include "vroc_params_t.h"
#include "vroc_candidates_t.h"

/* an array of states ready to encode (the messages point into it) */
typedef struct vrWireStates {
    int n;
    vroc_body_state_t *m;
} vrWireStates;

int vrWire_PutStates(vrWireStates *w, const vrUpdate *up);
void vrWire_FreeStates(vrWireStates *w);
/* appends the received states to up; -1 (up unchanged past its old end) if
 * any is malformed or names an id outside [0, max_id) */
int vrWire_GetStates(const vroc_body_state_t *m, int n, int max_id, vrUpdate *up);

/* the pairs touching at an island step: the message's arrays are allocated here */
int vrWire_PutTouches(vroc_candidates_t *m, const vrTouches *c);
void vrWire_FreeTouches(vroc_candidates_t *m);
/* appends; -1 when malformed (nothing appended) */
int vrWire_GetTouches(const vroc_candidates_t *m, int max_id, vrTouches *out);

void vrWire_PutDef(vroc_body_def_t *m, int id, const vrObjectDef *d, char *off_text);
int vrWire_GetDef(const vroc_body_def_t *m, vrObjectDef *d);
void vrWire_PutParams(vroc_params_t *m, const vrParams *p);
int vrWire_GetParams(const vroc_params_t *m, vrParams *p);
void vrWire_PutGrid(vroc_grid_t *m, const vrGrid *g);
int vrWire_GetGrid(const vroc_grid_t *m, vrGrid *g);

#endif
