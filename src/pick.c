/* pick.c — the first object a ray meets (SPEC 9: the mouse as the hand
 * clicks an object to grab it).  The ray meets the polygons as they are
 * drawn (the tessellation, not the analytic surface): what the pointer is
 * over on the screen is what is picked.  Each face is a fan of triangles,
 * met by the Moller-Trumbore test (1997) in the body frame. */
#include <math.h>
#include <stdlib.h>

#include "vroc.h"
#include "vec.h"

/* the ray's distance to triangle (a, b, c), or -1 when it misses */
static double ray_triangle(vec3 o, vec3 d, vec3 a, vec3 b, vec3 c)
{
    vec3 e1 = vec3_sub(b, a), e2 = vec3_sub(c, a), p = vec3_cross(d, e2), s, q;
    double det = vec3_dot(e1, p), u, v, t;
    if (fabs(det) < 1e-300) return -1;
    s = vec3_sub(o, a);
    u = vec3_dot(s, p) / det;
    if (u < 0 || u > 1) return -1;
    q = vec3_cross(s, e1);
    v = vec3_dot(d, q) / det;
    if (v < 0 || u + v > 1) return -1;
    t = vec3_dot(e2, q) / det;
    return t >= 0 ? t : -1;
}

static vec3 vertex(const vrMesh *m, int k)
{
    const double *p = m->verts + 3 * m->face_verts[k];
    return vec3_make(p[0], p[1], p[2]);
}

/* the nearest face the ray (body frame) meets, -1 for none */
static double ray_mesh(const vrMesh *m, vec3 o, vec3 d)
{
    double best = -1;
    int f, k;
    for (f = 0; f < m->nfaces; f++) {
        int a = m->face_start[f], b = m->face_start[f + 1];
        for (k = a + 1; k + 1 < b; k++) {
            double t = ray_triangle(o, d, vertex(m, a), vertex(m, k), vertex(m, k + 1));
            if (t >= 0 && (best < 0 || t < best)) best = t;
        }
    }
    return best;
}

static double ray_object(vrWorld *w, vrObjectId id, vec3 o, vec3 d)
{
    vrObjectState st;
    vrMesh m;
    quat q;
    vec3 c;
    if (vrWorld_GetObjectState(w, id, &st) || vrWorld_GetMesh(w, id, &m)) return -1;
    q = quat_make(st.orientation[0], st.orientation[1], st.orientation[2], st.orientation[3]);
    c = vec3_make(st.position[0], st.position[1], st.position[2]);
    return ray_mesh(&m, quat_unrotate(q, vec3_sub(o, c)), quat_unrotate(q, d));
}

int vrWorld_RayCast(vrWorld *w, const double origin[3], const double dir[3],
                    vrObjectId *hit, double *t)
{
    vec3 o = vec3_make(origin[0], origin[1], origin[2]), d = vec3_make(dir[0], dir[1], dir[2]);
    int n = vrWorld_ObjectCount(w), i;
    double best = -1;
    vrObjectId *ids = malloc((size_t)(n > 0 ? n : 1) * sizeof *ids);
    if (!ids) return -1;
    n = vrWorld_ObjectList(w, ids, n);
    for (i = 0; i < n; i++) {
        double ti = ray_object(w, ids[i], o, d);
        if (ti >= 0 && (best < 0 || ti < best)) best = ti, *hit = ids[i];
    }
    free(ids);
    if (best < 0) return -1;
    *t = best;
    return 0;
}
