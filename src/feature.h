/* feature.h — a convex polyhedron as its feature graph (SPEC 2): the
 * vrPolyhedron type, its features (vertex, edge, face) and small queries
 * over them.  Only types and inline functions: polyhedron.c builds the
 * graph, mass.c fills its mass properties, and everything that reads it
 * (the walk, the contact, the hull's checks) starts from here.
 *
 * Every collision shape but the true sphere is a convex polyhedron stored in
 * its body frame, whose origin is the centre of mass (built-in shapes are
 * built there; OFF files are shifted there).  The feature graph is what the
 * closest-feature walk (closest.c) moves on: vertices, edges and faces, each
 * knowing its neighbours, and faces knowing their planes.  Coplanar facets are
 * one face (a cube has 6 quads, not 12 triangles).
 *
 * Orientation conventions:
 *  - face_vert / face_edge list a face's boundary counter-clockwise seen from
 *    outside; face_edge[k] joins face_vert[k] and face_vert[k+1].
 *  - edge_v[e] = {tail, head}; edge_f[e] = {left, right}: seen from outside
 *    with the edge pointing up the page tail->head, `left` is the face on the
 *    left, for which tail->head runs counter-clockwise.
 *  - vert_edge lists the edges at a vertex (any order is allowed by the walk;
 *    the builder gives them counter-clockwise about the outward direction).
 */
#ifndef VROC_FEATURE_H
#define VROC_FEATURE_H

#include "vec.h"

enum { VR_VERTEX = 0, VR_EDGE = 1, VR_FACE = 2 };

typedef struct vrPolyhedron {
    int nv, ne, nf;
    vec3 *vert;            /* nv positions, body frame (centre of mass at 0) */
    vec3 *vert_normal;     /* nv smooth normals, for drawing only */
    int (*edge_v)[2];      /* ne: tail, head */
    int (*edge_f)[2];      /* ne: left, right face */
    int *vert_edge_start;  /* nv+1: edges of vertex v are vert_edge[start[v] .. start[v+1]) */
    int *vert_edge;
    int *face_start;       /* nf+1: boundary of face f is face_vert[start[f] .. start[f+1]) */
    int *face_vert;
    int *face_edge;
    vec3 *face_normal;     /* nf outward unit normals */
    double *face_offset;   /* nf: the plane is {x : n.x = offset}; offset > 0 */
    double *face_spread;   /* nf: how far the face's vertices lie apart along its normal (merged facets) */
    double *face_drop;     /* nf: how far the highest other vertex lies below its lowest one, along its normal */

    /* mass properties for uniform density (mass.c) */
    double volume;         /* geometric volume of the solid, m^3 */
    mat33 inertia_unit;    /* inertia tensor about the origin per unit mass */
    double r_in, r_out;    /* inscribed / circumscribed radius about the centre (thesis 3.3.1.1) */
    vec3 shift;            /* what was subtracted from the input points to put the centre of mass at 0 */
    struct vrFaceGroups *groups;   /* a big hull's faces by their normals (face_groups.h), else NULL */
} vrPolyhedron;

typedef struct vrFeature { int type; int index; } vrFeature; /* VR_VERTEX / VR_EDGE / VR_FACE */

static inline vrFeature vrFeature_Make(int type, int index)
{
    vrFeature f;
    f.type = type;
    f.index = index;
    return f;
}

/* does f name a feature of p (a cache from another polyhedron may not)? */
static inline int vrFeature_Valid(const vrPolyhedron *p, vrFeature f)
{
    int n[3];
    n[0] = p->nv, n[1] = p->ne, n[2] = p->nf;
    return (unsigned)f.type < 3 && (unsigned)f.index < (unsigned)n[f.type];
}

/* a vertex of feature f: where a search on p's graph starts */
static inline int vrFeature_Vertex(const vrPolyhedron *p, vrFeature f)
{
    return f.type == VR_VERTEX ? f.index : f.type == VR_EDGE ? p->edge_v[f.index][0] : p->face_vert[p->face_start[f.index]];
}

static inline int vrPolyhedron_FaceSize(const vrPolyhedron *p, int f) { return p->face_start[f + 1] - p->face_start[f]; }
static inline int vrPolyhedron_VertDegree(const vrPolyhedron *p, int v) { return p->vert_edge_start[v + 1] - p->vert_edge_start[v]; }
/* the vertex at the other end of edge e from its vertex v; branch-free, as
 * the walk's inner loops run over vertex stars */
static inline int vrPolyhedron_OtherEnd(const vrPolyhedron *p, int e, int v) { return p->edge_v[e][0] ^ p->edge_v[e][1] ^ v; }
/* how far x (body frame) lies above the plane of face f */
static inline double vrPolyhedron_FaceHeight(const vrPolyhedron *p, int f, vec3 x)
{
    /* NOLINTNEXTLINE(clang-analyzer-core.UndefinedBinaryOperatorResult): polyhedron.c sets every face's offset when it builds one */
    return vec3_dot(p->face_normal[f], x) - p->face_offset[f];
}

#endif
