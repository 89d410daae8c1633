/* face_groups.h — a big hull's faces grouped by the way they face (a cube
 * map of their normals), each group with a cone holding its normals and
 * its least plane offset.  The search for the face along which two shapes
 * lie farthest apart (contact.c's touching_axis) bounds a whole group from
 * these and skips it: a superquadric of 300 x 300 points has 90,000
 * faces, and that search looked at each of them at every touch. */
#ifndef VROC_FACE_GROUPS_H
#define VROC_FACE_GROUPS_H

#include "feature.h"

/* hulls of at most this many faces are not grouped (a scan is cheap) */
#define VR_FACE_GROUPS_MIN 512
/* cells per side of each of the cube map's six faces, and so the most groups */
#define VR_FACE_GROUP_CELLS 8
#define VR_FACE_GROUPS_MOST (6 * VR_FACE_GROUP_CELLS * VR_FACE_GROUP_CELLS)

typedef struct vrFaceGroup {
    vec3 axis;              /* unit; every normal of the group within the cone: */
    double cos_a, sin_a;    /* n.axis >= cos_a */
    double least_offset;    /* the least face_offset of the group */
    int start, n;           /* its faces: vrFaceGroups.face[start .. start + n), ascending */
} vrFaceGroup;

typedef struct vrFaceGroups {
    int n;
    vrFaceGroup *group;
    int *face;
} vrFaceGroups;

/* p's groups in p->groups (left NULL for a small hull); -1 on no memory */
int vrFaceGroups_Make(vrPolyhedron *p);
void vrFaceGroups_Free(vrFaceGroups *g);
/* Above n.o - offset for every face of the group, o in the body frame:
 * a face's gap bound (contact.c) is at most this, and a group whose bound
 * lies below what the search has found can be skipped. */
double vrFaceGroup_Bound(const vrFaceGroup *g, vec3 o);

#endif
