/* off.h — a convex polyhedron from an OFF file (off.c, SPEC 1.1). */
#ifndef VROC_OFF_H
#define VROC_OFF_H

#include "polyhedron.h"

/* the convex hull of an OFF or COFF file's vertices; refuses malformed
 * input, naming the file (and line where it applies) */
int vrPolyhedron_FromOFF(const char *path, vrPolyhedron **out, char *err, size_t errlen);
/* the same with the vertices scaled by scale[3] first (each component
 * VR_SCALE_MIN..VR_SCALE_MAX); when text is not NULL, *text receives a
 * malloc'ed OFF text of the scaled vertices that gives this polyhedron bit
 * for bit with scale 1 (what the workers get) */
int vrPolyhedron_FromOFFScaled(const char *path, const double scale[3], vrPolyhedron **out, char **text, char *err,
                               size_t errlen);

#endif
