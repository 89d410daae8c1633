/* panel_draw.c — the tool panel's boxes for the render module (SPEC 8).
 *
 *   Part            one box of the panel: centre and half extents in the sheet's frame, colour
 *   parts_of        the panel's boxes now (the knobs where knob_place puts them)
 *   box_mesh        a box's eight corners and six faces
 *   pose_matrix     sheet frame, then the box's centre: body to world
 *
 * Boxes, not the objects' meshes: the panel is an aid in the picture
 * (thesis A.1.1: "does not interfere with the simulation"), so the
 * library's object table never sees it.  Always solid: it is virtual,
 * whatever see_through does to real objects.
 */
#include <string.h>
#include "panel_draw.h"
#include "panel.h"
#include "world_state.h"

const unsigned char vrPanelDraw_SheetColor[3] = {170, 180, 200};

typedef struct Part {
    vec3 centre, half;
    unsigned char color[3];
} Part;

/* the faces of a box whose corner k is (k&1 ? +x : -x, k&2 ? +y : -y,
 * k&4 ? +z : -z), counter-clockwise from outside */
static const int box_faces[24] = {0, 4, 6, 2, 1, 3, 7, 5, 0, 1, 5, 4, 2, 6, 7, 3, 0, 2, 3, 1, 4, 5, 7, 6};
static const int box_starts[7] = {0, 4, 8, 12, 16, 20, 24};

static Part part(vec3 centre, vec3 half, int r, int g, int b)
{
    Part p;
    p.centre = centre, p.half = half;
    p.color[0] = (unsigned char)r, p.color[1] = (unsigned char)g, p.color[2] = (unsigned char)b;
    return p;
}

/* The sheet is 5 mm thick behind its plane; buttons (6 x 4 cm) stand 8 mm
 * in front of it, the lines 2 mm, the knobs (2 x 3 cm) 12 mm: all reach
 * through z = 0, where the controls' centres are.  Colours: stop red,
 * play green, step yellow, select blue (light blue while select = 1),
 * lines dark grey, knobs white. */
static void parts_of(const vrWorld *w, Part out[VR_PANEL_PARTS])
{
    static const int button_rgb[4][3] = {{220, 40, 40}, {40, 190, 60}, {230, 200, 40}, {50, 80, 190}};
    int c, k = 0;
    const vrSettings *s = vrWorld_Settings(w);
    out[k++] = part(vec3_make(0, 0, -0.0025), vec3_make(VR_PANEL_HALF_W, VR_PANEL_HALF_H, 0.0025),
                    vrPanelDraw_SheetColor[0], vrPanelDraw_SheetColor[1], vrPanelDraw_SheetColor[2]);
    for (c = VR_PANEL_STOP; c <= VR_PANEL_SELECT; c++) {
        const int *rgb = c == VR_PANEL_SELECT && s->select ? (const int[3]){140, 210, 255} : button_rgb[c];
        vec3 at = vrPanel_LocalCentre(w, (vrPanelControl)c);
        out[k++] = part(vec3_make(at.x, at.y, 0.002), vec3_make(0.03, 0.02, 0.004), rgb[0], rgb[1], rgb[2]);
    }
    for (c = VR_PANEL_TIME_STEP; c <= VR_PANEL_COLLISION_DIST; c++) {
        vec3 at = vrPanel_LocalCentre(w, (vrPanelControl)c);
        out[k++] = part(vec3_make(0, at.y, 0), vec3_make(VR_PANEL_SLIDER_HALF, 0.004, 0.002), 70, 70, 80);
        out[k++] = part(vec3_make(at.x, at.y, 0.003), vec3_make(0.01, 0.015, 0.006), 245, 245, 245);
    }
}

static void box_mesh(vec3 half, double verts[24])
{
    int k;
    for (k = 0; k < 8; k++) {
        verts[3 * k] = k & 1 ? half.x : -half.x;
        verts[3 * k + 1] = k & 2 ? half.y : -half.y;
        verts[3 * k + 2] = k & 4 ? half.z : -half.z;
    }
}

/* body to world, column-major (render.h): the sheet's pose, then the part's centre */
static void pose_matrix(const vrPanel *p, vec3 centre, double m[16])
{
    mat33 R = mat33_from_quat(p->q);
    vec3 at = vec3_add(p->p, mat33_mulv(&R, centre));
    int i, j;
    for (j = 0; j < 3; j++)
        for (i = 0; i < 3; i++) m[4 * j + i] = R.m[i][j];
    m[3] = m[7] = m[11] = 0;
    m[12] = at.x, m[13] = at.y, m[14] = at.z;
    m[15] = 1;
}

int vrPanelDraw_Parts(const vrWorld *w, vrPanelParts *parts, vrRenderObject *out)
{
    Part p[VR_PANEL_PARTS];
    int k;
    if (!vrWorld_Settings(w)->panel) return 0;
    parts_of(w, p);
    box_mesh(vec3_make(1, 1, 1), parts->normals);   /* unused: flat shading; the module wants them */
    for (k = 0; k < VR_PANEL_PARTS; k++) {
        vrRenderObject *o = &out[k];
        box_mesh(p[k].half, parts->verts[k]);
        o->nverts = 8, o->verts = parts->verts[k], o->normals = parts->normals;
        o->nfaces = 6, o->face_start = box_starts, o->face_verts = box_faces;
        o->smooth = 0;
        pose_matrix(&w->panel, p[k].centre, o->model);
        memcpy(o->color, p[k].color, 3);
        o->style = VR_STYLE_SOLID;
    }
    return VR_PANEL_PARTS;
}
