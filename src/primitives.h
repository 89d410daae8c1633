/* primitives.h — the built-in shapes of SPEC 2 as convex polyhedra (the
 * feature graph of feature.h).  All return 0 and set *out, or return -1
 * with a message in err (at most errlen bytes) and leave *out NULL. */
#ifndef VROC_PRIMITIVES_H
#define VROC_PRIMITIVES_H

#include "polyhedron.h"

/* SPEC 2 sphere mesh: vres latitude bands, ures longitude steps, single pole
 * vertices.  For drawing; the physics uses the true sphere. */
int vrPolyhedron_Sphere(double radius, int ures, int vres, vrPolyhedron **out, char *err, size_t errlen);
/* box of half extents half (all > 0): 8 vertices, 6 quads */
int vrPolyhedron_Cube(vec3 half, vrPolyhedron **out, char *err, size_t errlen);
/* SPEC 2 superquadric (Barr 1981): convex hull of the samples, coplanar facets merged */
int vrPolyhedron_Superquadric(double exp1, double exp2, vec3 radii, int ures, int vres,
                              vrPolyhedron **out, char *err, size_t errlen);

#endif
