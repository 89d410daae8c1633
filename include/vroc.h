/* vroc.h — public API of VROC, the Virtual and Real Object Collisions library.
 *
 * A world holds objects (spheres, cubes, superquadrics, convex polyhedra
 * from OFF files), static when their mass is negative, and the simulation
 * settings of the thesis's appendix A.  Objects are referred to by small
 * integer ids, valid until the object is deleted or the world restarted.
 * Functions return 0 on success and -1 on failure with a one-line message
 * in the caller's err buffer (no file/line prefix: the caller adds it).
 * Nothing here prints or exits, except the vrWorld_Write* functions, which
 * write to the stream they are given.
 *
 * ../shared/SPEC.md is the contract for the semantics; the man page
 * (man/vroc.1) is the user's view of it.
 */
#ifndef VROC_H
#define VROC_H

#include <stddef.h>
#include <stdio.h>

#ifdef __cplusplus
extern "C" {
#endif

#define VROC_VERSION "0.1.0"

typedef struct vrWorld vrWorld;
typedef int vrObjectId;
#define VR_NO_OBJECT (-1)

#define VR_NAME_MAX 63   /* bytes of an object name */
#define VR_PATH_MAX 1024

/* Sane limits (SPEC 11): the checks of vrObjectDef and vrSettings refuse
 * values outside them, so that no product of two of them overflows or
 * rounds to nothing (man vroc, LIMITS). */
#define VR_LENGTH_MIN 1e-6        /* m: sizes, radii, collision_dist */
#define VR_LENGTH_MAX 1e6         /* m: sizes and |coordinates| */
#define VR_MASS_MIN 1e-9          /* kg, and m^3 for a volume (it is the mass) */
#define VR_MASS_MAX 1e12
#define VR_SPEED_MAX 1e6          /* m/s and rad/s: |velocity components|, the caps */
#define VR_ACCEL_MAX 1e6          /* m/s^2: the global force's magnitude */
#define VR_TIME_MAX 1e3           /* s: time_step, internal_step */
#define VR_SCALE_MIN 1e-6         /* a polyhedron's scale factors */
#define VR_SCALE_MAX 1e6
#define VR_FRAME_STEPS_MAX 1000000 /* internal steps in one frame: more is refused */
/* The bound no frame passes however its spans' grids fall: twice the
 * frame's, because a frame checked at its start may still grow inside it
 * (speeds an event gives are capped, but a span's grid rounds up; loop.c),
 * and a worker refuses a grid longer than this, which no coordinator sends
 * (parallel/wire.c). */
#define VR_FRAME_STEPS_HARD_MAX (2 * VR_FRAME_STEPS_MAX)

typedef enum vrObjectType { VR_SPHERE, VR_CUBE, VR_SUPERQUADRIC, VR_POLYHEDRON } vrObjectType;

/* SPEC 1.3 `state` column */
typedef enum vrMotionState { VR_STATE_STATIC, VR_STATE_MOVING, VR_STATE_SUPPORTED, VR_STATE_REST } vrMotionState;

/* ---- objects (thesis tables A.1–A.4, SPEC 1.1) ------------------------- */
typedef struct vrObjectDef {
    vrObjectType type;
    double linear_vel[3];     /* m/s, (0,0,0) */
    double angular_vel[3];    /* rad/s, world frame, (0,0,0) */
    double elasticity;        /* coefficient of restitution 0..1, settings.default_elasticity (1.0) */
    double friction;          /* Coulomb coefficient 0..10, settings.default_friction (0); a pair
                                 uses sqrt(mu1 mu2) (SPEC 7) */
    double mass;              /* kg, != 0; < 0: static. Used when mass_set. */
    int mass_set;             /* an explicit mass wins over volume */
    double volume;            /* > 0, 1.0; the mass when mass_set == 0 */
    double translate[3];      /* modelling-frame origin, (0,0,0) */
    double rotate_axis[3];    /* rotation axis (!= 0) and angle (rad), when rotate_set */
    double rotate_angle;
    int rotate_set;
    int color[3];             /* 0..255, (255,0,0) */
    double radius;            /* sphere, 1.0 */
    int ures, vres;           /* sphere and superquadric tessellation 3..1000, 10 */
    double size[3];           /* cube half extents, (1,1,1) */
    double exp1, exp2;        /* superquadric exponents 0.05..2, 1.0 */
    double a1, a2, a3;        /* superquadric radii, 1.0 */
    char file[VR_PATH_MAX];   /* polyhedron: OFF file path (as the caller resolved it) */
    double scale[3];          /* polyhedron: the OFF vertices' scale factors, (1,1,1) */
    int real;                 /* 1: a model of a real object (see-through drawing) */
} vrObjectDef;

vrObjectDef vrObjectDef_Default(vrObjectType type);

/* ---- settings (thesis table A.5, SPEC 1.2) ----------------------------- */
typedef enum vrDistribution { VR_DIST_ROUND_ROBIN, VR_DIST_IMPROVED } vrDistribution;
/* how the pairs whose boxes meet are found: the same pairs (and bits) either way */
typedef enum vrBroadphaseKind { VR_BROADPHASE_SWEEP, VR_BROADPHASE_TREE } vrBroadphaseKind;

typedef struct vrSettings {
    double time_step;         /* >= 0, 0.1 (0 halts time) */
    double collision_dist;    /* > 0, 0.25 */
    double internal_step;     /* >= 0, 0 = automatic */
    double max_linear;        /* > 0, 8.0 */
    double max_angular;       /* > 0, 4.0 */
    double force_dir[3];      /* != 0, (0,0,-1) */
    double force_mag;         /* >= 0, 0 (no global force until `force` or `gravity`) */
    int heap;                 /* 1: scheduling heap; 0: every pair every internal step */
    int keep_looks;           /* 1: looks past an event at pairs it does not change stand; 0: made again (same bits) */
    vrBroadphaseKind broadphase; /* sorted sweep or box trees */
    long max_frames;          /* batch `start` limit, 600 */
    unsigned long long seed;  /* `random` stream seed, 0 */
    double room;              /* >= 0, 0 = no room for `random` */
    int gps;                  /* worker processes, 0 = serial */
    vrDistribution distribution;
    char lcm_url[256];        /* udpm://239.255.76.67:7667?ttl=0 */
    char collision_sound[256];/* the sound of collisions (SPEC 8): a file or a built-in; "" = bounce */
    double collision_vol;     /* 0..1, 1.0 */
    double default_friction;  /* 0..10, 0: the friction objects created after it start with */
    double default_elasticity;/* 0..1, 1: the elasticity objects created after it start with */
    double contact_step;      /* > 0 .. 0.1 s, 1/240: the longest step between island steps (SPEC 7) */
    double rest_speed;        /* 0..10 m/s, 0.05: a body with friction slower than this for 0.5 s rests (0: SPEC 3.5's rule alone) */
    double sound_min_speed;   /* >= 0, 0.5 m/s: the slowest impact that sounds (SPEC 8) */
    int select;               /* 0|1, 0: the hand's trigger grabs objects (1) or flies the view (SPEC 8) */
    double grab_reach;        /* 0..10 m, 0.1: how far from an object's surface the trigger grabs it */
    double fly_speed;         /* 0..1e6 m/s, 1: the trigger flies the view this fast (select = 0) */
    int hand_filter;          /* 0|1, 0: the 1-euro filter smooths the hand (SPEC 8's option) */
    double hand_min_cutoff;   /* 1e-3..1e3 Hz, 1: its cutoff at rest */
    double hand_beta;         /* 0..1e6 s/m, 10: how fast its cutoff rises with the hand's speed */
    int panel;                /* 0|1, 0: the virtual tool panel is drawn and takes the trigger (SPEC 8) */
} vrSettings;

vrSettings vrSettings_Default(void);

/* ---- the world --------------------------------------------------------- */
vrWorld *vrWorld_Create(void);
void vrWorld_Destroy(vrWorld *w);

const vrSettings *vrWorld_Settings(const vrWorld *w);
/* validates every field (ranges of SPEC 1.2); nothing changes on error.
 * Takes effect at the next frame, also while running. */
int vrWorld_SetSettings(vrWorld *w, const vrSettings *s, char *err, size_t errlen);

/* Creates an object with vrObjectDef_Default(type).  Names follow
 * [A-Za-z_][A-Za-z0-9_.-]* and are at most VR_NAME_MAX bytes; an existing
 * name is an error here (the shell selects it instead). */
int vrWorld_CreateObject(vrWorld *w, const char *name, vrObjectType type, vrObjectId *id,
                         char *err, size_t errlen);
vrObjectId vrWorld_FindObject(const vrWorld *w, const char *name);
const char *vrWorld_ObjectName(const vrWorld *w, vrObjectId id);
int vrWorld_GetObjectDef(const vrWorld *w, vrObjectId id, vrObjectDef *def);
/* Validates and stores the definition.  Geometry that can fail (an OFF file)
 * is loaded here, so its error reaches the statement that caused it.  After
 * the simulation has started, the object is re-instantiated at the next
 * frame (new shape, mass, pairs) and checked for interpenetration. */
int vrWorld_SetObjectDef(vrWorld *w, vrObjectId id, const vrObjectDef *def, char *err, size_t errlen);
int vrWorld_DeleteObject(vrWorld *w, vrObjectId id);
int vrWorld_ObjectCount(const vrWorld *w);
/* ids of all objects in creation order; returns the count (fills at most max) */
int vrWorld_ObjectList(const vrWorld *w, vrObjectId *ids, int max);

/* Instantiates what changed and refuses to go on if objects interpenetrate
 * (the message names each pair).  vrWorld_Step calls it as needed. */
int vrWorld_Start(vrWorld *w, char *err, size_t errlen);
/* Advances `frames` frames of time_step each. */
int vrWorld_Step(vrWorld *w, long frames, char *err, size_t errlen);
/* 1 when every dynamic object rests (or there is none) */
int vrWorld_AllAtRest(const vrWorld *w);
/* removes all objects; resets time, frames, statistics and the `random`
 * numbering; keeps settings */
void vrWorld_Restart(vrWorld *w);
/* SPEC 1.2 `random N`: N dynamic objects r<k> (and the room walls when
 * settings.room > 0), drawn from the seeded stream */
int vrWorld_AddRandom(vrWorld *w, int n, char *err, size_t errlen);

/* ---- state and output -------------------------------------------------- */
typedef struct vrObjectState {
    double t;
    double position[3];       /* modelling-frame origin (centre of mass) */
    double orientation[4];    /* unit quaternion w,x,y,z, body to world, canonical sign */
    double linear_vel[3];
    double angular_vel[3];    /* world frame */
    vrMotionState state;
} vrObjectState;
int vrWorld_GetObjectState(const vrWorld *w, vrObjectId id, vrObjectState *st);

typedef struct vrStats {
    long frames;
    double time;
    int objects, dynamic, resting;
    long pairs;
    long subframes;           /* internal steps in the last frame */
    long subframes_thesis;    /* ceil(time_step*2*max_linear/collision_dist) */
    long long checks, heap_pops, collisions, klu_solves, klu_refactors, klu_factors;
    double energy;
    double frame_ms, sim_ms, render_ms;
    long long island_steps;       /* island steps that solved an island (SPEC 7) */
    long long island_contacts;    /* the contacts those steps solved */
    long long clamps;             /* velocities max_linear or max_angular cut (SPEC 11) */
    /* with workers */
    int gps;
    long long messages;
    long long copies;             /* object instances over all workers */
    long long gp_checks[64];      /* per worker */
    long long gp_copies[64];      /* objects per worker (thesis table 5.5) */
    long long gp_pairs[64];       /* pairs per worker */
    long long foreign, malformed; /* messages ignored: other runs', undecodable */
    long long live_pairs;         /* pairs with a record now: those whose bodies' boxes meet (SPEC 10) */
    /* with workers (not in the stats line): the SGP's rounds, a request
     * and every answer to it, by kind: frame starts (and start checks),
     * events, advances, island steps, setups; the SGP's time in rounds
     * (waiting, and in-process workers' work); the workers' time on
     * requests, summed */
    long long rounds[5];
    double wait_ms, gp_busy_ms;
} vrStats;
void vrWorld_GetStats(const vrWorld *w, vrStats *st);
/* the renderer reports its time here so that `stats` can show render_ms */
void vrWorld_NoteRenderTime(vrWorld *w, double ms);

/* SPEC 1.3 formats: `dump` (header + one line per object, sorted by name)
 * and `stats` (one line of key=value). */
int vrWorld_WriteDump(const vrWorld *w, FILE *out);
int vrWorld_WriteStats(const vrWorld *w, FILE *out);
/* shortest decimal that reads back to the same double, -0 as 0 */
void vrFormatDouble(char buf[32], double x);

/* ---- save (SPEC 11) ------------------------------------------------------ */
/* def(ctx, out, id) writes object id's definition (the commands that make
 * it); the library writes the rest of the state as `state` lines.  The
 * pair owners are made anew at the next start, as the file's reader makes
 * them: both runs go on the same bits and the same counts.  -1 when out
 * fails. */
typedef void (*vrDefWriter)(void *ctx, FILE *out, vrObjectId id);
int vrWorld_WriteSave(vrWorld *w, FILE *out, vrDefWriter def, void *ctx);
/* one `state WORD key=value ...` line (text: what follows `state`) of a
 * saved file; selected: the object a `state body` belongs to */
int vrWorld_ReadState(vrWorld *w, vrObjectId selected, const char *text, size_t len, char *err, size_t errlen);
/* the shortest decimal that reads back to the same bits: -0 kept, inf as inf */
void vrFormatExact(char buf[32], double x);

/* ---- drawing ----------------------------------------------------------- */
/* The drawing mesh of an object, in its body frame: vertex positions and
 * smooth normals as xyz triples, faces as polygons (counter-clockwise seen
 * from outside).  smooth = 1 for spheres and superquadrics (Gouraud), 0 for
 * flat shading.  Pointers stay valid until the object changes. */
typedef struct vrMesh {
    int nverts;
    const double *verts;
    const double *normals;
    int nfaces;
    const int *face_start;    /* nfaces+1 */
    const int *face_verts;
    int smooth;
} vrMesh;
int vrWorld_GetMesh(vrWorld *w, vrObjectId id, vrMesh *mesh);

/* ---- display (SPEC 4): OSMesa stereo frames, loaded on first use ------- */
typedef struct vrView {
    int width, height;        /* 640x512, 16..8192 */
    double eye[3], look[3], up[3];  /* (0,-8,3), (0,0,1), (0,0,1) */
    double ipd;               /* 0.064 m */
    double focal;             /* 0 = |look - eye| */
    double fov;               /* vertical degrees, 45, 10..120 */
    int see_through;          /* 0 solid, 1 real objects wireframe, 2 real objects hidden */
} vrView;
vrView vrView_Default(void);

typedef struct vrDisplay vrDisplay;
/* loads the render module (vroc-render.so beside the executable, in
 * $VROC_RENDER_MODULE, or in the install's lib/vroc) and creates the
 * off-screen context */
int vrDisplay_Open(vrDisplay **out, char *err, size_t errlen);
void vrDisplay_Close(vrDisplay *d);
/* draws both eyes of the world's current state */
int vrDisplay_Render(vrDisplay *d, vrWorld *w, const vrView *view, char *err, size_t errlen);
/* the files a frame is written as: binary PPM or PNG (frames_format) */
typedef enum vrFrameFormat { VR_FRAMES_PPM, VR_FRAMES_PNG } vrFrameFormat;
/* writes the last render as frame-NNNNNN-left.EXT / -right.EXT into dir
 * (created if missing), EXT ppm or png */
int vrDisplay_WriteFrames(const vrDisplay *d, const char *dir, long frame, vrFrameFormat format,
                          char *err, size_t errlen);
/* the last render's pixels: eye 0 left, 1 right; RGB rows top to bottom */
const unsigned char *vrDisplay_Pixels(const vrDisplay *d, int eye, int *width, int *height);
const char *vrDisplay_RendererName(const vrDisplay *d);

/* ---- trackers: the head and the hand (SPEC 8) ------------------------- */
typedef enum vrDevice { VR_DEVICE_HEAD, VR_DEVICE_HAND } vrDevice;
#define VR_BUTTON_TRIGGER 1u
#define VR_BUTTON_RESELECT 2u

/* One tracker sample: a time, a position (m) and a unit quaternion (w, x,
 * y, z; body to world), and for the hand a button mask.  The head's frame
 * has the eyes at its origin, looking along its +y with its +z up (the
 * identity looks along the world's +y, upright); the hand points along
 * its +y. */
typedef struct vrTrackerSample {
    double t;
    double position[3];
    double orientation[4];
    unsigned buttons;
} vrTrackerSample;

/* A sample of dev at simulation time s->t (not before the device's last
 * sample: -1 and a message).  This is the one way samples come in: track
 * files, live trackers and a window's mouse all push here. */
int vrWorld_PushSample(vrWorld *w, vrDevice dev, const vrTrackerSample *s, char *err, size_t errlen);
/* dev's pose at the world's current time, interpolated between samples
 * (linear, slerp) and held after the last; -1 when dev has no sample */
int vrWorld_TrackerPose(const vrWorld *w, vrDevice dev, vrTrackerSample *out);
/* forgets dev's samples (the head: the view is the settings' again) */
void vrWorld_ClearTracker(vrWorld *w, vrDevice dev);
/* `track FILE`: the file's samples, their times taken from now (the
 * world's simulation time), replacing what the devices it names had
 * from now on.  The whole file is checked first: a bad line ("FILE:LINE:
 * message" in err) changes nothing. */
int vrWorld_ReadTrack(vrWorld *w, const char *path, char *err, size_t errlen);
/* simulation time now, and where the next frame ends (the bits the frame
 * loop computes: a frame's end is not time + time_step rounded) */
double vrWorld_Time(const vrWorld *w);
/* what the hand holds (select mode, SPEC 8), or VR_NO_OBJECT */
vrObjectId vrWorld_Held(const vrWorld *w);
/* how far the trigger has flown the viewpoint (outside select mode, SPEC
 * 8): added to the view's eye and look (and to a tracked head's) */
void vrWorld_FlyOffset(const vrWorld *w, double offset[3]);
double vrWorld_NextFrameEnd(const vrWorld *w);

/* a track file's samples in order, each handed to fn (its time as in the
 * file); an error names the file and the line */
typedef int (*vrTrackSampleFn)(void *user, vrDevice dev, const vrTrackerSample *s, char *err, size_t errlen);
int vrTrackFile_Read(const char *path, vrTrackSampleFn fn, void *user, char *err, size_t errlen);

/* the view the head pose gives: the eyes at its position, looking along
 * its +y, up its +z, converging as far away as view's focal distance
 * (focal, or |look - eye| when 0) */
void vrView_FromHead(vrView *view, const vrTrackerSample *head);

/* ---- collision sounds (SPEC 8) ----------------------------------------- */
#define VR_SOUND_DEFAULT "bounce"   /* the built-in sound, when collision_sound is empty */
/* One impact faster than sound_min_speed: its time, volume
 * (collision_vol * min(1, speed / 10 m/s)), the point where its impulse
 * acts, its approach speed and the pair.  At most one per pair per 0.1 s. */
typedef struct vrSoundEvent {
    double t;
    double volume;
    double position[3];
    double speed;
    vrObjectId a, b;
} vrSoundEvent;
/* the sound events of the last frame vrWorld_Step ran, in time order
 * (valid until the next step); returns their count */
int vrWorld_FrameSounds(const vrWorld *w, const vrSoundEvent **events);

/* ---- live trackers (SPEC 8) --------------------------------------------- */
/* Live trackers over LCM (SPEC 8): vroc.tracker_t messages on VROC_HEAD
 * and VROC_HAND, each carrying its track time; track time 0 is the
 * world's time at vrTrackers_Open.  Samples go into the world through
 * vrWorld_PushSample (a malformed or out-of-order message is dropped). */
typedef struct vrTrackers vrTrackers;
int vrTrackers_Open(vrTrackers **out, vrWorld *w, const char *url, char *err, size_t errlen);
void vrTrackers_Close(vrTrackers *tr);
/* Takes what has arrived; then, for up to `deadline` s of wall time after
 * each device's last message, waits until every device still sending has
 * a sample at or after T (the end of the frame to come), so that the
 * frame's poses are interpolated between the samples its track file
 * would give.  A device silent for `deadline` is no longer waited for
 * until it sends again.  Returns 1 while some device is sending. */
int vrTrackers_Poll(vrTrackers *tr, double T, double deadline);
/* waits up to `deadline` s for the first sample of any device: 1 if one came */
int vrTrackers_WaitFirst(vrTrackers *tr, double deadline);
/* messages dropped: undecodable, not finite, not unit, out of order */
long long vrTrackers_Refused(const vrTrackers *tr);
/* publishes sound events on VROC_SOUND (vroc.sound_t) */
int vrTrackers_PublishSounds(vrTrackers *tr, const vrSoundEvent *ev, int n, const char *sound);
/* ---- the virtual tool panel (SPEC 8, thesis A.1) ---------------------- */
/* Its controls, in `show panel`'s order: the four buttons, then the two
 * sliders.  The panel is a 45 x 25 cm sheet in the world, worked by the
 * hand's trigger (src/panel.c; man vroc, TOOL PANEL). */
typedef enum vrPanelControl {
    VR_PANEL_STOP, VR_PANEL_PLAY, VR_PANEL_STEP, VR_PANEL_SELECT,
    VR_PANEL_TIME_STEP, VR_PANEL_COLLISION_DIST, VR_PANEL_CONTROLS
} vrPanelControl;
#define VR_PANEL_REQUESTS_MAX 32   /* button presses kept between two reads */
/* "stop", "play", "step", "select", "time_step", "collision_dist" */
const char *vrPanel_ControlName(vrPanelControl c);
/* a control's centre in world coordinates (a slider's: its knob's, where
 * a held knob is, else where its setting puts it); -1 for no control */
int vrWorld_PanelControl(const vrWorld *w, vrPanelControl c, double centre[3]);
/* the sheet's pose: its centre and the unit quaternion (w, x, y, z) from
 * its frame (x along the 45 cm, y up the 25 cm, z its front's normal) to
 * the world's */
void vrWorld_PanelPose(const vrWorld *w, double position[3], double orientation[4]);
/* Takes the stop, play and step presses since the last call, oldest
 * first, at most max; returns their count.  The library only records
 * them: time runs where its caller runs frames (the shell's start, stop,
 * step), so the caller acts on them after each frame.  (select acts at
 * once; the sliders at the next frame boundary, in vrWorld_Step.) */
int vrWorld_PanelRequests(vrWorld *w, vrPanelControl *out, int max);

/* ---- the live window (SPEC 9): GLFW, loaded on first use ------------- */
/* The window shows a display's last render: mono (the left image of a view
 * rendered with ipd 0), side (left | right) or anaglyph (red from the left
 * eye, green and blue from the right).  vroc-window.so is dlopen()ed by the
 * first vrWindow_Open, so nothing of X, GL or GLFW is loaded before. */
typedef enum vrWindowMode { VR_WINDOW_MONO, VR_WINDOW_SIDE, VR_WINDOW_ANAGLYPH } vrWindowMode;
typedef enum vrWindowEventType {
    VR_WEV_PRESS, VR_WEV_RELEASE,   /* a mouse button (1 left, 2 middle, 3 right) */
    VR_WEV_MOTION,                  /* the pointer moved */
    VR_WEV_SCROLL,                  /* the wheel: amount > 0 away from the user */
    VR_WEV_KEY,                     /* a key went down: key is ASCII, lower case; 27 Esc */
    VR_WEV_CLOSE,                   /* the window manager's close button */
    VR_WEV_RESIZE                   /* the window's size changed: width x height */
} vrWindowEventType;
typedef struct vrWindowEvent {
    vrWindowEventType type;
    double x, y;                    /* the pointer, pixels from the top left */
    int button, key;
    int width, height;              /* VR_WEV_RESIZE: the new size, pixels */
    double amount;
    double time;                    /* monotonic seconds when it was taken */
} vrWindowEvent;
typedef struct vrWindow vrWindow;
/* fails with a clear message when $DISPLAY is unset or no X server answers */
int vrWindow_Open(vrWindow **out, char *err, size_t errlen);
void vrWindow_Close(vrWindow *win);
/* shows d's last render in mode: the window takes its size from it until
 * the user resizes the window; from then on the window keeps the user's
 * size and the image is drawn at its top left (draw it at vrWindow_Size) */
int vrWindow_Show(vrWindow *win, const vrDisplay *d, vrWindowMode mode, char *err, size_t errlen);
/* the window's size in pixels; 1 when the user (or the window manager)
 * chose it, 0 while it follows the images shown */
int vrWindow_Size(const vrWindow *win, int *width, int *height);
/* the events since the last call, at most max; never blocks */
int vrWindow_Poll(vrWindow *win, vrWindowEvent *ev, int max);

/* the virtual trackball (thesis chapter 5's HP-750): a drag of (dx, dy)
 * pixels (y down) turns the scene about look by pi*|d|/height radians,
 * about the axis dx*u + dy*r (u, r: the screen's up and right): eye and up
 * turn the other way.  Zoom: each wheel step brings the eye 10 % nearer
 * look (amount < 0: further). */
void vrView_Trackball(vrView *v, double dx, double dy);
void vrView_Zoom(vrView *v, double amount);
/* the ray from the head (the centre eye) through the pixel at (x, y) of a
 * width x height image of v (x, y from the top left, continuous) */
void vrView_PointerRay(const vrView *v, double x, double y, int width, int height,
                       double origin[3], double dir[3]);
/* the first object a ray meets (its polygons, as drawn), its distance t
 * along dir (unit); -1 when it meets none */
int vrWorld_RayCast(vrWorld *w, const double origin[3], const double dir[3],
                    vrObjectId *hit, double *t);

/* ---- workers (SPEC 5) ---------------------------------------------------- */
/* The loop of a worker process (`vroc-gp URL`): announces itself on the LCM
 * URL until a shell claims it, serves that shell's run, and returns when the
 * shell shuts the run down.  -1 with a message when the URL cannot be
 * opened. */
int vrWorker_Run(const char *url, char *err, size_t errlen);

#ifdef __cplusplus
}
#endif
#endif
