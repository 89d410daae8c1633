/* world.c — a world's life (create, restart, destroy), its settings, and
 * its objects by name and id as include/vroc.h shows them.  The frame
 * loop is loop.c; world_state.h lists the coordinator's files.
 *
 *   clear_objects  every object goes, and the pairs with them
 */
#include <stdlib.h>
#include <string.h>
#include "config.h"
#include "resume.h"
#include "parallel/spawn.h"
#include "tracker.h"
#include "start.h"

vrWorld *vrWorld_Create(void)
{
    vrWorld *w = calloc(1, sizeof *w);
    if (!w) return NULL;
    w->s = vrSettings_Default();
    w->instant_t = -INFINITY;
    w->contact_structure = -1;   /* the contact set is found at the first island step */
    w->still_structure = -1;
    vrUpdate_Init(&w->update);
    vrUpdate_Init(&w->pending);
    vrInstantLog_Init(&w->instant_log);
    vrSplitmix_Seed(&w->rng, w->s.seed);
    vrPanel_Init(&w->panel);
    vrGrab_Init(&w->grab);
    return w;
}

static void clear_objects(vrWorld *w)
{
    vrTable_Clear(&w->table);
    w->ndyn = 0;
    vrOwner_Free(w->owner);
    w->owner = NULL;
    w->started = 0;
    w->pending.n = 0;
    w->structure++;
}

void vrWorld_Destroy(vrWorld *w)
{
    if (!w) return;
    clear_objects(w);
    vrSgp_Free(w->sgp);
    vrTable_Free(&w->table);
    free(w->dyn);
    free(w->dyn_slot);
    vrReach_Free(&w->reach);
    free(w->changed);
    vrUpdate_Free(&w->update);
    vrUpdate_Free(&w->pending);
    vrInstantLog_Free(&w->instant_log);
    vrTouches_Free(&w->touches);
    free(w->contact_ids);
    vrIslandScratch_Free(&w->solve_scratch);
    free(w->isl_work.id);
    free(w->isl_work.body);
    free(w->isl_work.c);
    free(w->isl_work.pushed);
    free(w->isl_parent);
    free(w->isl_in);
    free(w->isl_slot);
    free(w->isl_ids);
    vrWarm_Free(&w->warm);
    vrWarm_Free(&w->warm_next);
    vrWorld_FreeTrackers(w);
    vrSounds_Free(&w->sounds);
    vrSave_Free(w);
    free(w);
}

void vrWorld_Restart(vrWorld *w)
{
    clear_objects(w);
    w->t = w->t_base = 0;
    w->frames = w->frames_base = 0;
    w->subframes = 0;
    w->collisions = w->island_steps = w->island_contacts = w->clamps = 0;
    w->frame_ms = w->sim_ms = w->render_ms = 0;
    memset(&w->retired, 0, sizeof w->retired);
    w->random_next = 0;
    w->params_dirty = 0;
    w->instant = 0;
    w->instant_t = -INFINITY;
    w->contact_structure = -1;   /* the contact set is found at the first island step */
    w->still_structure = -1;
    vrWorld_ClearTracker(w, VR_DEVICE_HEAD);   /* track time was time since `track` */
    vrWorld_ClearTracker(w, VR_DEVICE_HAND);
    vrSounds_Clear(&w->sounds);
    vrPanel_Restart(&w->panel);
    vrGrab_Init(&w->grab);
    vrSplitmix_Seed(&w->rng, w->s.seed);
    vrSave_Free(w);
    w->warm.n = 0;
}

const vrSettings *vrWorld_Settings(const vrWorld *w) { return &w->s; }

int vrWorld_SetSettings(vrWorld *w, const vrSettings *s, char *err, size_t n)
{
    return vrWorld_TakeSettings(w, s, err, n);
}

/* ---- objects by name and id ------------------------------------------------------------ */

vrObjectId vrWorld_FindObject(const vrWorld *w, const char *name) { return vrTable_Find(&w->table, name); }

int vrWorld_CreateObject(vrWorld *w, const char *name, vrObjectType type, vrObjectId *id, char *err, size_t n)
{
    int k;
    if (vrTable_Add(&w->table, name, type, &k, err, n) != 0) return -1;
    /* SPEC 7: objects start with the defaults set before them */
    w->table.obj[k]->def.elasticity = w->s.default_elasticity;
    w->table.obj[k]->def.friction = w->s.default_friction;
    if (id) *id = k;
    return 0;
}

const char *vrWorld_ObjectName(const vrWorld *w, vrObjectId id)
{
    vrObject *o = vrWorld_Object(w, id);
    return o ? o->name : NULL;
}

int vrWorld_GetObjectDef(const vrWorld *w, vrObjectId id, vrObjectDef *def)
{
    vrObject *o = vrWorld_Object(w, id);
    if (!o) return -1;
    *def = o->def;
    return 0;
}

int vrWorld_ObjectCount(const vrWorld *w) { return vrTable_Count(&w->table); }

int vrWorld_ObjectList(const vrWorld *w, vrObjectId *ids, int max) { return vrTable_List(&w->table, ids, max); }
