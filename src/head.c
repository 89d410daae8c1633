/* head.c — the view a tracked head gives (SPEC 8, thesis 3.4.1): both
 * eyes follow it, about the head pose as about `eye` (display.c makes
 * the two eyes of a view). */
#include "vroc.h"
#include "vec.h"

void vrView_FromHead(vrView *view, const vrTrackerSample *head)
{
    quat q = quat_make(head->orientation[0], head->orientation[1], head->orientation[2], head->orientation[3]);
    vec3 eye = vec3_make(view->eye[0], view->eye[1], view->eye[2]);
    vec3 look = vec3_make(view->look[0], view->look[1], view->look[2]);
    double dist = view->focal > 0 ? view->focal : vec3_dist(look, eye);
    vec3 p = vec3_make(head->position[0], head->position[1], head->position[2]);
    vec3 forward = quat_rotate(quat_normalize(q), vec3_make(0, 1, 0));
    vec3 up = quat_rotate(quat_normalize(q), vec3_make(0, 0, 1));
    if (!(dist > 0)) dist = 1;
    look = vec3_madd(p, dist, forward);
    view->eye[0] = p.x, view->eye[1] = p.y, view->eye[2] = p.z;
    view->look[0] = look.x, view->look[1] = look.y, view->look[2] = look.z;
    view->up[0] = up.x, view->up[1] = up.y, view->up[2] = up.z;
    view->focal = dist;
}
