/* shape.h — what collides (SPEC 2): a true sphere, a box or a polyhedron,
 * and its support point along a direction.  The type the contact floor
 * (penetration.c, sphere.c, contact.c) and the bodies share. */
#ifndef VROC_SHAPE_H
#define VROC_SHAPE_H

#include "feature.h"

typedef enum { VR_SHAPE_SPHERE, VR_SHAPE_BOX, VR_SHAPE_POLY } vrShapeKind;

/* What collides.  A sphere collides as a true sphere (its mesh is only for
 * drawing); a box is a polyhedron with closed forms against spheres. */
typedef struct vrShape {
    vrShapeKind kind;
    double radius;              /* sphere */
    vec3 half;                  /* box half extents */
    const vrPolyhedron *poly;   /* box and poly: the hull, body frame */
    unsigned long serial;       /* which making of the shape (a new one for every edit that
                                   remakes it): what a memo of contacts keys on, not the
                                   address, which a new hull may reuse */
} vrShape;

/* The posed shape's point farthest along dir (non-zero): a sphere's surface
 * point, a polyhedron's vertex (the first of equals: a scan's answer,
 * found by a climb over a hull of many vertices).  libccd's support
 * function, and how far a shape reaches along a direction. */
vec3 vrShape_Support(const vrShape *s, const vrPose *p, vec3 dir);
/* the same, the climb starting at *hint (a vertex index; -1 or out of
 * range: vertex 0), which gets the vertex found: calls along nearby
 * directions (libccd's) climb little */
vec3 vrShape_SupportFrom(const vrShape *s, const vrPose *p, vec3 dir, int *hint);
/* the index of that vertex of hull p along d in p's own frame, a climb
 * over a hull of many vertices starting at `start`: a pure function of p
 * and d, wherever the climb starts (a climb alone stops at whichever of
 * tied tops it meets first) */
int vrShape_TopVertex(const vrPolyhedron *p, vec3 d, int start);

#endif
