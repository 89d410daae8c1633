/* shape_share.h — one built shape per shape in a process: objects whose
 * definitions give the same shape (its type and numbers, to the bit: a
 * sphere's radius and tessellation, a cube's half sizes, a superquadric's
 * exponents, radii and tessellation) share one polyhedron and one drawing
 * mesh.  `random N`'s thousands of equal spheres and cubes are two shapes:
 * a default sphere's polyhedron and mesh are 26 kB, and each object had
 * its own.  A shape never changes once made (the walks, supports and
 * drawing only read it); it is freed with its last object.  An OFF
 * polyhedron's shape is its object's own (vrShape_Own): its file is read
 * anew at each edit. */
#ifndef VROC_SHAPE_SHARE_H
#define VROC_SHAPE_SHARE_H

#include "polyhedron.h"
#include "vroc.h"

typedef struct vrSharedShape vrSharedShape;

struct vrSharedShape {
    vrPolyhedron *poly;                  /* the hull, or a sphere's drawing mesh */
    double *draw_verts, *draw_normals;   /* the mesh as vrMesh arrays (query.c) */
    int *draw_face_start, *draw_face_verts;
    /* the share's own */
    int refs;
    int interned;                        /* in the process's table (not an OFF polyhedron) */
    unsigned long long hash;
    vrObjectDef key;                     /* the shape's fields of the definition, the rest zero */
    vrSharedShape *next;                 /* in its bucket */
};

/* the shape of d (a sphere, cube or superquadric), made the first time
 * and shared after: one more reference.  NULL with err on failure. */
vrSharedShape *vrShape_Share(const vrObjectDef *d, char *err, size_t n);
/* an OFF polyhedron made a shape of its own (one reference); the shape
 * owns it from here.  NULL when out of memory (poly is then freed). */
vrSharedShape *vrShape_Own(vrPolyhedron *poly);
/* one reference fewer; the shape goes with the last (s may be NULL) */
void vrShape_Release(vrSharedShape *s);
/* distinct shapes alive in the process (the tests') */
int vrShape_Count(void);

#endif
