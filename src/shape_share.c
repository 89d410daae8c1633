/* shape_share.c — one built shape per shape in a process (shape_share.h).
 *
 *   key_of       the definition's shape fields, the rest zero: equal keys, equal shapes
 *   hash_of      FNV-1a over the key's bytes
 *   make_mesh    the polyhedron's drawing mesh as vrMesh arrays
 *   make_shape   a new shape around a polyhedron
 *   find / grow_table / intern   the process's table of shared shapes
 *   vrShape_*    sharing, owning, releasing
 *
 * The table is the process's (a forked worker gets a copy of it, whose
 * references are its own): objects of every world and worker table in the
 * process share through it.  VROC steps a world from one thread.
 */
#include <stdlib.h>
#include <string.h>
#include "shape_share.h"
#include "primitives.h"
#include "config.h"

static vrSharedShape **bucket;   /* chains by hash; NULL while no shape is shared */
static int nbuckets, nshared, nalive;

static vrObjectDef key_of(const vrObjectDef *d)
{
    vrObjectDef k;
    memset(&k, 0, sizeof k);
    k.type = d->type;
    switch (d->type) {
    case VR_SPHERE:
        k.radius = d->radius, k.ures = d->ures, k.vres = d->vres;
        break;
    case VR_CUBE:
        memcpy(k.size, d->size, sizeof k.size);
        break;
    default:
        k.exp1 = d->exp1, k.exp2 = d->exp2, k.a1 = d->a1, k.a2 = d->a2, k.a3 = d->a3;
        k.ures = d->ures, k.vres = d->vres;
        break;
    }
    return k;
}

static unsigned long long hash_of(const vrObjectDef *k)
{
    const unsigned char *p = (const unsigned char *)k;
    unsigned long long h = 1469598103934665603ULL;
    size_t i;
    for (i = 0; i < sizeof *k; i++) h = (h ^ p[i]) * 1099511628211ULL;
    return h;
}

static int make_mesh(vrSharedShape *s)
{
    const vrPolyhedron *p = s->poly;
    int i, nfv = p->face_start[p->nf];
    s->draw_verts = malloc((size_t)p->nv * 3 * sizeof(double));
    s->draw_normals = malloc((size_t)p->nv * 3 * sizeof(double));
    s->draw_face_start = malloc((size_t)(p->nf + 1) * sizeof(int));
    s->draw_face_verts = malloc((size_t)nfv * sizeof(int));
    if (!s->draw_verts || !s->draw_normals || !s->draw_face_start || !s->draw_face_verts) return -1;
    for (i = 0; i < p->nv; i++) {
        s->draw_verts[3 * i] = p->vert[i].x;
        s->draw_verts[3 * i + 1] = p->vert[i].y;
        s->draw_verts[3 * i + 2] = p->vert[i].z;
        s->draw_normals[3 * i] = p->vert_normal[i].x;
        s->draw_normals[3 * i + 1] = p->vert_normal[i].y;
        s->draw_normals[3 * i + 2] = p->vert_normal[i].z;
    }
    memcpy(s->draw_face_start, p->face_start, (size_t)(p->nf + 1) * sizeof(int));
    memcpy(s->draw_face_verts, p->face_vert, (size_t)nfv * sizeof(int));
    return 0;
}

static void free_shape(vrSharedShape *s)
{
    vrPolyhedron_Free(s->poly);
    free(s->draw_verts);
    free(s->draw_normals);
    free(s->draw_face_start);
    free(s->draw_face_verts);
    free(s);
    nalive--;
}

/* a shape of one reference around poly (freed with it on failure) */
static vrSharedShape *make_shape(vrPolyhedron *poly)
{
    vrSharedShape *s = calloc(1, sizeof *s);
    if (!s) {
        vrPolyhedron_Free(poly);
        return NULL;
    }
    nalive++;
    s->poly = poly;
    s->refs = 1;
    if (make_mesh(s) != 0) {
        free_shape(s);
        return NULL;
    }
    return s;
}

static vrSharedShape *find(const vrObjectDef *k, unsigned long long h)
{
    vrSharedShape *s;
    if (!bucket) return NULL;
    for (s = bucket[h & (unsigned long long)(nbuckets - 1)]; s; s = s->next)
        if (s->hash == h && memcmp(&s->key, k, sizeof *k) == 0) return s;
    return NULL;
}

/* room for one more shape: the buckets double when they are all taken */
static int grow_table(void)
{
    int n = nbuckets ? 2 * nbuckets : 64, i;
    vrSharedShape **b;
    if (nshared + 1 <= nbuckets) return 0;
    if (!(b = calloc((size_t)n, sizeof(vrSharedShape *)))) return -1;   /* the buckets are pointers */
    for (i = 0; i < nbuckets; i++)
        while (bucket[i]) {
            vrSharedShape *s = bucket[i];
            bucket[i] = s->next;
            s->next = b[s->hash & (unsigned long long)(n - 1)];
            b[s->hash & (unsigned long long)(n - 1)] = s;
        }
    free(bucket);
    bucket = b;
    nbuckets = n;
    return 0;
}

static int intern(vrSharedShape *s)
{
    vrSharedShape **head;
    if (grow_table() != 0) return -1;
    head = &bucket[s->hash & (unsigned long long)(nbuckets - 1)];
    s->next = *head;
    *head = s;
    s->interned = 1;
    nshared++;
    return 0;
}

static void unintern(vrSharedShape *s)
{
    vrSharedShape **p = &bucket[s->hash & (unsigned long long)(nbuckets - 1)];
    while (*p != s) p = &(*p)->next;
    *p = s->next;
    if (--nshared == 0) {   /* the last: the table goes too (nothing left for a leak check) */
        free(bucket);
        bucket = NULL;
        nbuckets = 0;
    }
}

static int make_polyhedron(const vrObjectDef *d, vrPolyhedron **out, char *err, size_t n)
{
    switch (d->type) {
    case VR_SPHERE:
        return vrPolyhedron_Sphere(d->radius, d->ures, d->vres, out, err, n);
    case VR_CUBE:
        return vrPolyhedron_Cube(vrVec3_Of(d->size), out, err, n);
    default:
        return vrPolyhedron_Superquadric(d->exp1, d->exp2, vec3_make(d->a1, d->a2, d->a3), d->ures, d->vres, out,
                                         err, n);
    }
}

vrSharedShape *vrShape_Share(const vrObjectDef *d, char *err, size_t n)
{
    vrObjectDef k = key_of(d);
    unsigned long long h = hash_of(&k);
    vrSharedShape *s = find(&k, h);
    vrPolyhedron *poly = NULL;
    if (s) {
        s->refs++;
        return s;
    }
    if (make_polyhedron(d, &poly, err, n) != 0) return NULL;
    if (!(s = make_shape(poly))) {
        vrGeom_Fail(err, n, "out of memory");
        return NULL;
    }
    s->key = k;
    s->hash = h;
    (void)intern(s);   /* out of memory: unshared, it still serves its object */
    return s;
}

vrSharedShape *vrShape_Own(vrPolyhedron *poly) { return make_shape(poly); }

void vrShape_Release(vrSharedShape *s)
{
    if (!s || --s->refs > 0) return;
    if (s->interned) unintern(s);
    free_shape(s);
}

int vrShape_Count(void) { return nalive; }
