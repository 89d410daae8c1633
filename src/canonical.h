/* canonical.h — the canonical support features, distance and normal of a
 * posed pair of polyhedra (canonical.c).  Internal to the contact floor
 * (contact.c, region.c, sphere.c) and its tests: what others use is
 * contact.h. */
#ifndef VROC_CANONICAL_H
#define VROC_CANONICAL_H

#include "feature.h"
#include "vertex_set.h"

/* a polyhedron at a pose */
typedef struct vrPosed { const vrPolyhedron *p; const vrPose *pose; } vrPosed;

static inline vec3 vrPosed_Vertex(const vrPosed *b, int i) { return vrPose_apply(b->pose, b->p->vert[i]); }
/* the world plane n.x = *h of face f; returns n */
static inline vec3 vrPosed_FacePlane(const vrPosed *b, int f, double *h)
{
    vec3 n = vrPose_rotate(b->pose, b->p->face_normal[f]);
    *h = b->p->face_offset[f] + vec3_dot(n, b->pose->p);
    return n;
}

/* a support feature (Mirtich's features) and its vertices */
typedef struct vrSupportFeature {
    int kind, index;   /* VR_VERTEX / VR_EDGE / VR_FACE and its index (an edge -1: the
                          segment between the farthest two of v, vrSupportFeature_Find) */
    vrIntSet v;        /* its vertices, ascending */
} vrSupportFeature;

/* The support feature of b along world dir, searched from the walk's
 * feature `from` (s->v initialised by the caller); -1 when out of memory. */
int vrSupportFeature_Find(const vrPosed *b, vec3 dir, vrFeature from, vrSupportFeature *s);
/* end points of a vertex or edge support feature, world (a vertex twice) */
void vrSupportFeature_Segment(const vrPosed *b, const vrSupportFeature *s, vec3 *p0, vec3 *p1);

/* the canonical pair: features, normal, distance, closest points */
typedef struct vrCanon {
    vrSupportFeature sa, sb;
    vec3 n;          /* world, from a toward b */
    double dist;
    vec3 qa, qb;     /* closest points (canonical choice on ties) */
    double ha, hb;   /* support planes n.x = ha (of a) and n.x = hb (of b) */
} vrCanon;

void vrCanon_Init(vrCanon *c);
void vrCanon_Free(vrCanon *c);
/* The support features along dir (a) and -dir (b), searched from the walk's
 * features fa, fb, then normal, distance and closest points from them;
 * -1 when out of memory. */
int vrCanon_Compute(const vrPosed *a, const vrPosed *b, vec3 dir, vrFeature fa, vrFeature fb, vrCanon *c);

/* edges this near parallel (the sine of their angle, squared) have no
 * cross product to go by */
#define VR_PARALLEL_SIN2 1e-12

/* v normalised, or +z when it has no direction */
static inline vec3 vrUnitOrUp(vec3 v)
{
    v = vec3_normalize(v);
    return vec3_len2(v) > 0 ? v : vec3_make(0, 0, 1);
}


#endif
