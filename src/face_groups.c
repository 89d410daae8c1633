/* face_groups.c — a big hull's faces grouped by their normals (see
 * face_groups.h).
 *   cell_of          a normal's cell of the cube map
 *   vrFaceGroups_Make, vrFaceGroups_Free, vrFaceGroup_Bound */
#include <stdlib.h>
#include "face_groups.h"

#define CELLS VR_FACE_GROUP_CELLS
#define NCELLS VR_FACE_GROUPS_MOST

/* what rounding in the dot products and the cone may leave a bound short
 * of (m per metre of |o|, and m): far above it, far below any gap a face
 * that could win is off the best by (contact.c's BOUND_SLACK is 1e-9) */
#define BOUND_MARGIN 1e-9
#define CONE_SLACK 1e-6   /* rad */

static int cell_of(vec3 n)
{
    double a[3] = {n.x, n.y, n.z}, m;
    int k = 0, i, j, side, u, v;
    for (i = 1; i < 3; i++)
        if (fabs(a[i]) > fabs(a[k])) k = i;
    m = fabs(a[k]);
    side = a[k] > 0;
    i = (k + 1) % 3, j = (k + 2) % 3;
    u = (int)((a[i] / m + 1) * 0.5 * CELLS);
    v = (int)((a[j] / m + 1) * 0.5 * CELLS);
    u = u < 0 ? 0 : u >= CELLS ? CELLS - 1 : u;
    v = v < 0 ? 0 : v >= CELLS ? CELLS - 1 : v;
    return ((k * 2 + side) * CELLS + u) * CELLS + v;
}

/* the cone of group g: its axis the mean normal, its angle the widest */
static void make_cone(const vrPolyhedron *p, vrFaceGroup *g, const int *face)
{
    vec3 sum = vec3_zero();
    double c, a;
    int i;
    g->least_offset = HUGE_VAL;
    for (i = 0; i < g->n; i++) {
        sum = vec3_add(sum, p->face_normal[face[g->start + i]]);
        g->least_offset = vr_min(g->least_offset, p->face_offset[face[g->start + i]]);
    }
    g->axis = vec3_normalize(sum);
    c = 1;
    for (i = 0; i < g->n; i++) c = vr_min(c, vec3_dot(g->axis, p->face_normal[face[g->start + i]]));
    /* widened by CONE_SLACK: a cone of nearly parallel normals is only
     * known to within rounding, and its angle's cosine says little */
    a = acos(vr_max(-1, vr_min(1, c))) + CONE_SLACK;
    g->cos_a = a < 0.5 * VR_PI ? cos(a) : -1;   /* -1: a cone too wide to bound */
    g->sin_a = sin(a);
}

int vrFaceGroups_Make(vrPolyhedron *p)
{
    vrFaceGroups *gs;
    int count[NCELLS + 1] = {0}, *cell, f, c, n = 0;
    p->groups = NULL;
    if (p->nf <= VR_FACE_GROUPS_MIN) return 0;
    gs = calloc(1, sizeof *gs);
    cell = malloc((size_t)p->nf * sizeof *cell);
    if (gs) gs->face = malloc((size_t)p->nf * sizeof *gs->face);
    if (gs) gs->group = malloc(NCELLS * sizeof *gs->group);
    if (!gs || !cell || !gs->face || !gs->group) {
        free(cell);
        vrFaceGroups_Free(gs);
        return -1;
    }
    for (f = 0; f < p->nf; f++) count[(cell[f] = cell_of(p->face_normal[f])) + 1]++;
    for (c = 0; c < NCELLS; c++) count[c + 1] += count[c];
    for (c = 0; c < NCELLS; c++)
        if (count[c + 1] > count[c]) {
            gs->group[n].start = count[c];
            gs->group[n].n = count[c + 1] - count[c];
            n++;
        }
    for (f = 0; f < p->nf; f++) gs->face[count[cell[f]]++] = f;   /* ascending within a cell */
    gs->n = n;
    for (c = 0; c < n; c++) make_cone(p, &gs->group[c], gs->face);
    free(cell);
    p->groups = gs;
    return 0;
}

void vrFaceGroups_Free(vrFaceGroups *g)
{
    if (!g) return;
    free(g->group);
    free(g->face);
    free(g);
}

/* n.o is largest at the normal nearest o's direction the cone allows: o's
 * own if it is inside the cone (|o|), else on the cone's rim, toward o
 * (A cos_a + B sin_a, A and B o's parts along the axis and across it) */
double vrFaceGroup_Bound(const vrFaceGroup *g, vec3 o)
{
    double len = vec3_len(o), A = vec3_dot(g->axis, o), B = sqrt(vr_max(0, len * len - A * A)), top;
    if (g->cos_a <= -1) return HUGE_VAL;
    top = A >= len * g->cos_a ? len : A * g->cos_a + B * g->sin_a;
    return top - g->least_offset + BOUND_MARGIN * (1 + len);
}
