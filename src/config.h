/* config.h — what the user sets: settings (SPEC 1.2) and object
 * definitions (SPEC 1.1).  Their defaults, the checks a value passes before
 * the world takes it, and what settings give the pair owners. */
#ifndef VROC_CONFIG_H
#define VROC_CONFIG_H

#include "vroc.h"
#include "owner.h"
#include "polyhedron.h"

/* a definition's or a setting's vector (double[3]) as a vec3 */
static inline vec3 vrVec3_Of(const double a[3]) { return vec3_make(a[0], a[1], a[2]); }

/* the most workers (the `gps` setting's range) */
#define VR_MAX_GPS 64

/* 0, or an error in err (the setting or field named) and -1 */
int vrSettings_Check(const vrSettings *s, char *err, size_t n);
int vrObjectDef_Check(const vrObjectDef *d, char *err, size_t n);

/* the free flight and the owners' parameters the settings give */
vrFlight vrSettings_Flight(const vrSettings *s);
vrParams vrSettings_Params(const vrSettings *s);

/* What a change of settings does: the pair owners take the new parameters
 * (VR_PARAMS_OWNERS: every pair is looked at afresh), and where free flight
 * changes every body is re-anchored at the frame start (VR_PARAMS_MOTION).
 * The heap and the broadphase change no motion: re-anchoring for it would round poses
 * differently from a run that never switched it (SPEC 3.2: heap on and off
 * give the same bits, and so does switching between them). */
enum { VR_PARAMS_OWNERS = 1, VR_PARAMS_MOTION = 2 };
int vrSettings_Changes(const vrSettings *from, const vrSettings *to);

#endif
