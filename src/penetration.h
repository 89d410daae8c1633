/* penetration.h — depth and direction of overlapping shapes by libccd's MPR
 * (penetration.c, SPEC 3.1). */
#ifndef VROC_PENETRATION_H
#define VROC_PENETRATION_H

#include "shape.h"

/* Called by the contact (contact.c) when polyhedra overlap (spheres use
 * closed forms); exposed for tests.  Returns 0 when they overlap (depth >= 0,
 * unit dir from a toward b: translating b by depth * dir makes them touch,
 * pos a point in the overlap), -1 when they do not.  MPR's depth is along
 * the portal it refines from the centre line: exact for spheres, not always
 * the minimum for polyhedra. */
int vrPenetration(const vrShape *a, const vrPose *pa, const vrShape *b, const vrPose *pb,
                  double *depth, vec3 *dir, vec3 *pos);

#endif
