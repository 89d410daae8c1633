/* sphere.c — what a true sphere's centre sees of the other shape, by closed
 * forms (SPEC 2, thesis 3.2.1 [Glassner90]): a sphere, a box, or any other
 * polyhedron by the walk to the centre and the canonical support feature
 * toward it.  Depths are exact.  contact.c turns them into the sphere's
 * contact.
 *   near_posed               a posed polyhedron's, for vrNear_Poly
 */
#include <stddef.h>

#include "canonical.h"
#include "separation.h"
#include "segment.h"
#include "sphere.h"

vrNear vrNear_Sphere(vec3 centre, double r, vec3 c)
{
    vrNear nr;
    nr.dir = vrUnitOrUp(vec3_sub(c, centre));
    nr.dist = vec3_dist(c, centre) - r;
    nr.q = vec3_madd(centre, r, nr.dir);
    return nr;
}

/* closed form: clamp the centre into the box (its frame); inside, the
 * nearest face (lowest axis on ties) */
vrNear vrNear_Box(const vrShape *box, const vrPose *pose, vec3 c)
{
    /* q zeroed only for gcc -fanalyzer, which does not see the loop fill it */
    double x[3], h[3] = {box->half.x, box->half.y, box->half.z}, q[3] = {0, 0, 0};
    vec3 xl = vrPose_invapply(pose, c);
    int i, inside = 1, axis = 0;
    vrNear nr;
    x[0] = xl.x, x[1] = xl.y, x[2] = xl.z;
    for (i = 0; i < 3; i++) {
        q[i] = x[i] < -h[i] ? -h[i] : x[i] > h[i] ? h[i] : x[i];
        if (q[i] != x[i]) inside = 0;
        if (h[i] - fabs(x[i]) < h[axis] - fabs(x[axis])) axis = i;
    }
    if (inside) {
        double s = x[axis] < 0 ? -1 : 1;
        nr.dist = -(h[axis] - fabs(x[axis]));
        q[axis] = s * h[axis];
        nr.dir = vrPose_rotate(pose, vec3_make(axis == 0 ? s : 0, axis == 1 ? s : 0, axis == 2 ? s : 0));
    } else {
        vec3 diff = vec3_sub(xl, vec3_make(q[0], q[1], q[2]));
        nr.dist = vec3_len(diff);
        nr.dir = vrPose_rotate(pose, vec3_scale(diff, 1.0 / nr.dist));
    }
    nr.q = vrPose_apply(pose, vec3_make(q[0], q[1], q[2]));
    return nr;
}

/* the walk to the centre, then the canonical support feature toward it */
static int near_posed(const vrPosed *b, vec3 c, vrWalkCache *cache, int *steps, vrNear *nr)
{
    vrSupportFeature s;
    vrGap g;
    vec3 q, dir;
    double dw = vrClosest_WalkPoint(b->p, b->pose, c, cache, &q, steps);
    vrFeature f = cache->a;
    if (f.type == VR_FACE && dw <= 0) { /* inside: the walk scanned every face plane */
        double h;
        nr->dir = vrPosed_FacePlane(b, f.index, &h);
        nr->dist = vec3_dot(nr->dir, c) - h;
        nr->q = vec3_madd(c, -nr->dist, nr->dir);
        return 0;
    }
    if (!(dw > 0)) { /* the centre on an edge or vertex */
        nr->dir = vrUnitOrUp(vec3_sub(c, b->pose->p));
        nr->dist = 0;
        nr->q = c;
        return 0;
    }
    g.a = b, g.b = NULL, g.c = c, g.va = vrFeature_Vertex(b->p, f), g.vb = 0;
    dir = vrGap_WalkDirection(&g, f, f, q, c, dw);
    vrIntSet_Init(&s.v);
    if (vrSupportFeature_Find(b, dir, f, &s)) {
        vrIntSet_Free(&s.v);
        return -1;
    }
    if (s.kind == VR_FACE) {
        double h;
        nr->dir = vrPosed_FacePlane(b, s.index, &h);
        nr->dist = vec3_dot(nr->dir, c) - h;
        nr->q = vec3_madd(c, -nr->dist, nr->dir);
    } else {
        vec3 p0, p1;
        vrSupportFeature_Segment(b, &s, &p0, &p1);
        nr->q = vec3_lerp(p0, p1, vrSegment_PointParam(p0, p1, c));
        nr->dist = vec3_dist(c, nr->q);
        nr->dir = nr->dist > 0 ? vec3_scale(vec3_sub(c, nr->q), 1 / nr->dist) : dir;
    }
    vrIntSet_Free(&s.v);
    return 0;
}

int vrNear_Poly(const vrPolyhedron *p, const vrPose *pose, vec3 c, vrWalkCache *cache, int *steps, vrNear *nr)
{
    vrPosed b;
    b.p = p, b.pose = pose;
    return near_posed(&b, c, cache, steps, nr);
}
