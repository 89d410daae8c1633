/* build.h — an object made from its definition: its hull or sphere, its
 * drawing mesh, its mass properties, and the initial state the definition
 * describes.  The world and the workers build with the same code, so every
 * copy of an object moves the same bits. */
#ifndef VROC_BUILD_H
#define VROC_BUILD_H

#include "table.h"

/* shape and mass properties from o->def (a polyhedron from o->off) */
int vrObject_Build(vrObject *o, char *err, size_t n);
/* the initial state the definition describes, at time t */
/* the initial state the definition describes, at time t; returns the
 * speed clamps it took (stats clamps) */
int vrObject_Place(vrObject *o, double t, const vrFlight *f);
/* built when it is not; placed at t while it is not in the simulation
 * (the clamps of that are added to *clamps when it is not NULL) */
int vrObject_Ready(vrObject *o, double t, const vrFlight *f, long long *clamps, char *err, size_t n);

/* a definition's mass: the given one, or its volume at unit density */
double vrObjectDef_Mass(const vrObjectDef *d);
quat vrObjectDef_Orientation(const vrObjectDef *d);
/* does going from a to b need a new shape, or new mass properties? */
int vrObjectDef_ShapeChanged(const vrObjectDef *a, const vrObjectDef *b);
int vrObjectDef_MassChanged(const vrObjectDef *a, const vrObjectDef *b);
/* the angular momentum of b turning at omega in orientation q */
vec3 vrBody_MomentumAt(const vrBody *b, quat q, vec3 omega);

#endif
