/* panel_draw.h — the tool panel as the frames show it (SPEC 8): the
 * sheet, its buttons, its sliders' lines and knobs as flat-shaded boxes
 * for the render module (render.h).  They are drawn, never simulated: no
 * object, no pair, nothing in dump or stats. */
#ifndef VROC_PANEL_DRAW_H
#define VROC_PANEL_DRAW_H

#include "vroc.h"
#include "render.h"

/* the sheet, four buttons, two lines and two knobs */
#define VR_PANEL_PARTS 9

/* the boxes' meshes, kept by the caller while the frame is drawn */
typedef struct vrPanelParts {
    double verts[VR_PANEL_PARTS][8 * 3];
    double normals[8 * 3];
} vrPanelParts;

/* the sheet's colour (man vroc, TOOL PANEL) */
extern const unsigned char vrPanelDraw_SheetColor[3];

/* fills out[0..VR_PANEL_PARTS) and returns VR_PANEL_PARTS, or 0 when the
 * panel is off (settings.panel = 0) */
int vrPanelDraw_Parts(const vrWorld *w, vrPanelParts *parts, vrRenderObject *out);

#endif
