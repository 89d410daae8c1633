/* off.h — a convex polyhedron from an OFF file (off.c, SPEC 1.1). */
#ifndef VROC_OFF_H
#define VROC_OFF_H

#include "polyhedron.h"

/* an OFF file describing a convex polyhedron; refuses non-convex or
 * malformed input, naming the file (and line where it applies) */
int vrPolyhedron_FromOFF(const char *path, vrPolyhedron **out, char *err, size_t errlen);

#endif
