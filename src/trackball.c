/* trackball.c — the view under mouse control (SPEC 9; thesis chapter 5:
 * the HP-750's "virtual trackball under mouse control").
 *
 *   vrView_Trackball   a drag turns the scene about the point looked at
 *   vrView_Zoom        the wheel moves the eye along its line of sight
 *   vrView_PointerRay  the ray under a pixel, for picking (pick.c)
 *
 * The trackball is the linear virtual sphere: the scene turns as if the
 * pointer dragged the front of a ball centred on look, one window height
 * of drag turning it half a turn.  The head pose (eye, up) turns the other
 * way, so the frames written and `eye` follow the window.
 */
#include <math.h>

#include "vroc.h"
#include "vec.h"

#define ZOOM_STEP 0.9        /* the eye's distance to look per wheel step */
#define ZOOM_MIN 1e-3        /* m: the eye never reaches look */

static vec3 v3(const double p[3]) { return vec3_make(p[0], p[1], p[2]); }
static void put(vec3 v, double p[3]) { p[0] = v.x, p[1] = v.y, p[2] = v.z; }

/* the screen's axes: f into the screen, r right, u up */
static void screen_axes(const vrView *v, vec3 *f, vec3 *r, vec3 *u)
{
    *f = vec3_normalize(vec3_sub(v3(v->look), v3(v->eye)));
    *r = vec3_normalize(vec3_cross(*f, v3(v->up)));
    *u = vec3_cross(*r, *f);
}

void vrView_Trackball(vrView *v, double dx, double dy)
{
    vec3 f, r, u, axis, look = v3(v->look);
    double len = sqrt(dx * dx + dy * dy);
    quat q;
    if (len == 0 || v->height < 1) return;
    screen_axes(v, &f, &r, &u);
    /* a drag right turns the front right (about u), a drag down turns it
     * down (about r); the eye turns by the opposite angle */
    axis = vec3_normalize(vec3_add(vec3_scale(u, dx), vec3_scale(r, dy)));
    q = quat_from_axis_angle(axis, -VR_PI * len / v->height);
    put(vec3_add(look, quat_rotate(q, vec3_sub(v3(v->eye), look))), v->eye);
    put(quat_rotate(q, u), v->up);
}

void vrView_Zoom(vrView *v, double amount)
{
    vec3 look = v3(v->look), to_eye = vec3_sub(v3(v->eye), look);
    double d = vec3_len(to_eye), nd = d * pow(ZOOM_STEP, amount);
    if (d == 0) return;
    if (nd < ZOOM_MIN) nd = ZOOM_MIN;
    put(vec3_madd(look, nd / d, to_eye), v->eye);
}

void vrView_PointerRay(const vrView *v, double x, double y, int width, int height,
                       double origin[3], double dir[3])
{
    vec3 f, r, u;
    double t = tan(v->fov * VR_PI / 360.0), sx, sy;
    screen_axes(v, &f, &r, &u);
    sx = (2 * x / width - 1) * t * width / height;
    sy = (1 - 2 * y / height) * t;
    put(v3(v->eye), origin);
    put(vec3_normalize(vec3_add(f, vec3_add(vec3_scale(r, sx), vec3_scale(u, sy)))), dir);
}
