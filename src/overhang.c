/* overhang.c — a support feature that reaches past a face, measured over
 * the face only (SPEC 3.2's canonical distance; canonical.c face_against).
 *
 * The canonical distance of a face against the other body's support
 * feature is the feature's lowest point over the face's plane.  An edge
 * or a face within SUPPORT_TOL of parallel to the face may reach past it
 * (a floor's 6 m edge under a 9 cm box face tilted 4e-12 rad): its lowest
 * vertex then lies metres beyond the face, and below the true distance,
 * which the walk finds (8e-11 m in test_contact, 1.07e-11 m in the edit
 * fuzzer's seed 6785, whose impact came a halving earlier or later as a
 * look trusted the walk or not).  So the feature is clipped, in the
 * face's plane, to the face, and the clipped part measured: its lowest
 * point is a corner (the feature's height is affine over it), the
 * feature's own vertex where it has one there, else interpolated.  A
 * feature wholly over the face is measured as before, vertex by vertex.
 *   project, over_face       the face plane's 2-D frame; a point over the face
 *   height_of                the feature's height over a point of the plane
 *   corner_height            a corner's height: a vertex's own where it is one
 *   clip                     the face and the feature's hulls intersected
 *
 * No static state; scratch memory lives on the stack unless the two
 * outgrow it.
 */
#include <stdlib.h>
#include <string.h>

#include "convex2d.h"
#include "overhang.h"

/* the face's plane: outward normal n, (t1, t2, n) right-handed */
typedef struct Frame { vec3 n, t1, t2; } Frame;

/* the feature's height n.x as an affine function of the plane's point:
 * an edge's along its ends e0, e1 (heights h0, h1), a face's on its
 * plane no.x = ho */
typedef struct Height {
    int is_face;
    P2 e0, e1;
    double h0, h1;
    vec3 no;
    double ho;
} Height;

static P2 project(const Frame *fr, vec3 x) { return p2(vec3_dot(fr->t1, x), vec3_dot(fr->t2, x)); }

static vec3 lift(const Frame *fr, P2 q, double h)
{
    return vec3_madd(vec3_add(vec3_scale(fr->t1, q.x), vec3_scale(fr->t2, q.y)), h, fr->n);
}

/* is q over the face, its boundary counter-clockwise about n, within VR_REGION_SLACK? */
static int over_face(const P2 *face, int nf, P2 q)
{
    int i;
    for (i = 0; i < nf; i++) {
        P2 a = face[i], b = face[(i + 1) % nf];
        if (p2_turn(a, b, q) < -VR_REGION_SLACK * p2_len(p2_sub(b, a))) return 0;
    }
    return 1;
}

static Height height_of(const Frame *fr, const vrPosed *other, const vrSupportFeature *s)
{
    Height hf;
    vec3 e0, e1;
    memset(&hf, 0, sizeof hf);
    hf.is_face = s->kind == VR_FACE;
    if (hf.is_face) {
        hf.no = vrPosed_FacePlane(other, s->index, &hf.ho);
        return hf;
    }
    vrSupportFeature_Segment(other, s, &e0, &e1);
    hf.e0 = project(fr, e0), hf.e1 = project(fr, e1);
    hf.h0 = vec3_dot(fr->n, e0), hf.h1 = vec3_dot(fr->n, e1);
    return hf;
}

static double height_at(const Frame *fr, const Height *hf, P2 q)
{
    P2 d = p2_sub(hf->e1, hf->e0);
    double u;
    if (hf->is_face) return (hf->ho - vec3_dot(hf->no, lift(fr, q, 0))) / vec3_dot(hf->no, fr->n);
    u = p2_dot(d, d) > 0 ? p2_dot(p2_sub(q, hf->e0), d) / p2_dot(d, d) : 0;
    u = u < 0 ? 0 : u > 1 ? 1 : u;
    return hf->h0 + u * (hf->h1 - hf->h0);
}

/* corner q of the clipped part: the lowest of the feature's vertices at
 * it (within the clipping's tolerance), else the feature's height there */
static double corner_height(const Frame *fr, const Height *hf, const vrPosed *other, const vrIntSet *s, P2 q)
{
    double h = HUGE_VAL;
    int i;
    for (i = 0; i < s->n; i++) {
        vec3 x = vrPosed_Vertex(other, s->v[i]);
        P2 p = project(fr, x);
        if (fabs(p.x - q.x) <= VR_REGION_SLACK && fabs(p.y - q.y) <= VR_REGION_SLACK) h = vr_min(h, vec3_dot(fr->n, x));
    }
    return h < HUGE_VAL ? h : height_at(fr, hf, q);
}

/* the face's and the feature's hulls (face: nf points, feature: ns, from
 * buf) intersected into res; buf holds 5 (nf + ns) + 4 points */
static int clip(P2 *buf, int nf, int ns, P2 **res)
{
    P2 *face = buf, *set = face + nf, *tmp = set + ns, *scratch = tmp + 2 * (nf + ns) + 2;
    int hf = vrP2_Hull(face, nf, tmp), hs = vrP2_Hull(set, ns, tmp);
    *res = tmp;
    return vrP2_IntersectHulls(face, hf, set, hs, tmp, scratch);
}

int vrOverhang_Lowest(const vrPosed *fb, int f, vec3 n, const vrPosed *other, const vrSupportFeature *s, double *low,
                      vec3 *at)
{
    const vrPolyhedron *p = fb->p;
    P2 stack[96], *buf = stack, *res, mid = p2(0, 0);
    int nf = vrPolyhedron_FaceSize(p, f), ns = s->v.n, i, m, beyond = 0;
    Frame fr;
    Height hf;
    if (s->kind == VR_VERTEX) return 0;
    if (5 * (nf + ns) + 4 > 96 && !(buf = malloc((5 * (size_t)(nf + ns) + 4) * sizeof *buf))) return -1;
    fr.n = n, fr.t1 = vec3_orthogonal(n), fr.t2 = vec3_cross(n, fr.t1);
    for (i = 0; i < nf; i++) buf[i] = project(&fr, vrPosed_Vertex(fb, p->face_vert[p->face_start[f] + i]));
    for (i = 0; i < ns; i++) {
        buf[nf + i] = project(&fr, vrPosed_Vertex(other, s->v.v[i]));
        beyond |= !over_face(buf, nf, buf[nf + i]);
    }
    m = beyond ? clip(buf, nf, ns, &res) : 0;
    if (m > 0) {
        hf = height_of(&fr, other, s);
        *low = HUGE_VAL;
        for (i = 0; i < m; i++) {
            *low = vr_min(*low, corner_height(&fr, &hf, other, &s->v, res[i]));
            mid = p2(mid.x + res[i].x / m, mid.y + res[i].y / m);
        }
        *at = lift(&fr, mid, height_at(&fr, &hf, mid));
    }
    if (buf != stack) free(buf);
    return m > 0;
}
