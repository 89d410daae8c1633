/* mass.h — mass properties of a convex polyhedron for uniform density
 * (SPEC 2: volume, centre of mass, inertia by the divergence theorem) and
 * principal axes of an inertia tensor. */
#ifndef VROC_MASS_H
#define VROC_MASS_H

#include "feature.h"

/* fills volume, inertia_unit, r_in, r_out of a polyhedron whose vertices
 * are already centred (divergence theorem over the faces) */
void vrMass_Compute(vrPolyhedron *p);
/* volume and centre of mass of a closed polyhedron given by its faces */
void vrMass_VolumeCentroid(const vrPolyhedron *p, double *volume, vec3 *centroid);
/* principal moments (ascending) and the rotation whose columns are the
 * principal axes (body frame), of a symmetric matrix, by Jacobi sweeps */
void vrMass_Principal(const mat33 *inertia, vec3 *moments, mat33 *axes);

#endif
