/* polyhedron.h — convex polyhedra with their feature graph (SPEC 2).
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
#ifndef VROC_POLYHEDRON_H
#define VROC_POLYHEDRON_H

#include <stddef.h>
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
} vrPolyhedron;

/* Builders.  All return 0 and set *out, or return -1 with a message in err
 * (NUL-terminated, at most errlen bytes) and leave *out NULL.  None prints. */

/* SPEC 2 sphere mesh: vres latitude bands, ures longitude steps, single pole
 * vertices.  For drawing; the physics uses the true sphere. */
int vrPolyhedron_Sphere(double radius, int ures, int vres, vrPolyhedron **out, char *err, size_t errlen);
/* box of half extents half (all > 0): 8 vertices, 6 quads */
int vrPolyhedron_Cube(vec3 half, vrPolyhedron **out, char *err, size_t errlen);
/* SPEC 2 superquadric (Barr 1981): convex hull of the samples, coplanar facets merged */
int vrPolyhedron_Superquadric(double exp1, double exp2, vec3 radii, int ures, int vres,
                              vrPolyhedron **out, char *err, size_t errlen);
/* convex hull of points (relative tolerance 1e-9 for coplanarity); refuses
 * fewer than 4 non-coplanar points */
int vrPolyhedron_Hull(const vec3 *pts, int n, vrPolyhedron **out, char *err, size_t errlen);
/* an OFF file describing a convex polyhedron; refuses non-convex or
 * malformed input, naming the file (and line where it applies) */
int vrPolyhedron_FromOFF(const char *path, vrPolyhedron **out, char *err, size_t errlen);
void vrPolyhedron_Free(vrPolyhedron *p);

/* helpers over the graph */
static inline int vrPolyhedron_FaceSize(const vrPolyhedron *p, int f) { return p->face_start[f + 1] - p->face_start[f]; }
static inline int vrPolyhedron_VertDegree(const vrPolyhedron *p, int v) { return p->vert_edge_start[v + 1] - p->vert_edge_start[v]; }
/* the vertex at the other end of edge e from its vertex v; branch-free, as
 * the walk's inner loops run over vertex stars */
static inline int vrPolyhedron_OtherEnd(const vrPolyhedron *p, int e, int v) { return p->edge_v[e][0] ^ p->edge_v[e][1] ^ v; }
/* The top vertex along d (body frame), climbing from v to a higher
 * neighbour until none is: on a convex polyhedron that vertex is the top.
 * *gap, if not NULL, receives how far it stands above its highest
 * neighbour. */
int vrPolyhedron_Climb(const vrPolyhedron *p, vec3 d, int v, double *gap);

/* mass.c: fills volume, inertia_unit, r_in, r_out of a polyhedron whose
 * vertices are already centred (divergence theorem over the faces). */
void vrMass_Compute(vrPolyhedron *p);
/* volume and centre of mass of a closed polyhedron given by its faces */
void vrMass_VolumeCentroid(const vrPolyhedron *p, double *volume, vec3 *centroid);
/* principal moments (ascending) and the rotation whose columns are the
 * principal axes (body frame), of a symmetric matrix, by Jacobi sweeps */
void vrMass_Principal(const mat33 *inertia, vec3 *moments, mat33 *axes);

/* ---- shared by the geometry files (polyhedron.c, hull.c, off.c) --------- */

/* relative tolerance (of the shape's size, the diagonal of its bounding
 * box) within which facets count as coplanar (SPEC 2) */
#define VR_COPLANAR_TOL 1e-9

/* A polyhedron from its vertices and the boundary loops of its faces
 * (counter-clockwise seen from outside, convex, every vertex used, closed
 * 2-manifold): centres it on its centre of mass, computes planes, the feature
 * graph, area-weighted smooth normals and the mass properties.  Refuses a
 * surface that is not closed, not planar or not convex within tol (relative). */
int vrPolyhedron_FromFaces(const vec3 *vert, int nv, const int *face_start, const int *face_vert, int nf,
                           double tol, vrPolyhedron **out, char *err, size_t errlen);
/* vrPolyhedron_Hull with its relative tolerance tol.  When src is not NULL,
 * *src receives a malloc'ed array of nv entries: the index in pts of each
 * vertex of the result (the caller frees it). */
int vrPolyhedron_HullTol(const vec3 *pts, int n, double tol, int **src, vrPolyhedron **out, char *err,
                         size_t errlen);
/* the diagonal of the bounding box of n points: the size tolerances scale with */
double vrGeom_Size(const vec3 *pts, int n);
/* formats a message into err (when err is not NULL and errlen > 0); returns -1 */
int vrGeom_Fail(char *err, size_t errlen, const char *fmt, ...);

#endif
