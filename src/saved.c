/* saved.c — an object placed at its saved state (saved.h). */
#include "saved.h"

void vrSaved_Place(vrObject *o, const vrFlight *f)
{
    const vrSavedBody *s = o->saved;
    vrBodyState st = s->anchor;
    st.id = o->body.id;
    vrBody_Apply(&o->body, &st, f);
    o->frame_pose = s->frame_pose;
    o->have_frame_pose = s->have_frame_pose;
    o->frame_pose_lazy = 0;   /* the file's pose, taken */
    o->quiet_frames = s->quiet_frames;
    o->slow_frames = s->slow_frames;
    o->slow_start = s->slow_start;
}
