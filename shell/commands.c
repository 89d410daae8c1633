/* commands.c — the command table (thesis appendix A plus the SPEC 1.2
 * extensions), the statement parser and the dispatcher.
 *
 * A line is parsed and range-checked completely before its handler runs,
 * so a bad line changes nothing (SPEC 1.4).  Handlers report failures in
 * err; the dispatcher adds the file and line.
 */
#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>
#include "commands.h"
#include "lexer.h"

/* the ranges are the library's sane limits (vroc.h VR_*_MIN/MAX, SPEC 11) */

static const char *const distributions[] = {"round_robin", "improved", NULL};
static const char *const broadphases[] = {"sweep", "tree", NULL};   /* vrBroadphaseKind's order */
static const char *const frame_formats[] = {"ppm", "png", NULL};
static const char *const window_modes[] = {"mono", "side", "anaglyph", NULL};

#define OBJ_CMD(nm, what) \
    {nm, nm " NAME", what, NULL, G_OBJECT, F_NAME, K_NONE, R_ANY, 0, 0, 0, NULL, T_NONE, 0, 0, run_object}
#define ATTR(nm, syn, what, def, kind, range, lo, hi, field, types) \
    {nm, syn, what, def, G_ATTR, F_ASSIGN, kind, range, lo, hi, 0, NULL, T_OBJECT, offsetof(vrObjectDef, field), types, run_attr}
#define SETTING(nm, syn, what, def, group, kind, range, lo, hi, field) \
    {nm, syn, what, def, group, F_ASSIGN, kind, range, lo, hi, 0, NULL, T_SETTINGS, offsetof(vrSettings, field), 0, run_setting}
#define TEXT_SETTING(nm, syn, what, def, group, kind, empty, maxlen, field) \
    {nm, syn, what, def, group, F_ASSIGN, kind, R_ANY, 0, maxlen, empty, NULL, T_SETTINGS, offsetof(vrSettings, field), 0, run_setting}
#define VIEW(nm, syn, what, def, kind, range, lo, hi, field) \
    {nm, syn, what, def, G_VIEW, F_ASSIGN, kind, range, lo, hi, 0, NULL, T_VIEW, offsetof(vrView, field), 0, run_view}
#define VERB(nm, syn, what, group, form, range, lo, hi, run) \
    {nm, syn, what, NULL, group, form, K_NONE, range, lo, hi, 0, NULL, T_NONE, 0, 0, run}

const Command sh_commands[] = {
    OBJ_CMD("sphere", "create or select the sphere NAME"),
    OBJ_CMD("cube", "create or select the cube NAME"),
    OBJ_CMD("superquadric", "create or select the superquadric NAME"),
    OBJ_CMD("polyhedron", "create or select the polyhedron NAME (an OFF file's hull)"),

    ATTR("linear_vel", "linear_vel = (x,y,z)", "initial linear velocity, m/s", "(0,0,0)", K_VEC3, R_CLOSED, -VR_SPEED_MAX, VR_SPEED_MAX, linear_vel, TY_ALL),
    ATTR("angular_vel", "angular_vel = (x,y,z)", "initial angular velocity, rad/s, world frame", "(0,0,0)", K_VEC3, R_CLOSED, -VR_SPEED_MAX, VR_SPEED_MAX, angular_vel, TY_ALL),
    ATTR("elasticity", "elasticity = e", "coefficient of restitution (1: no energy lost)", "default_elasticity", K_NUM, R_CLOSED, 0, 1, elasticity, TY_ALL),
    ATTR("friction", "friction = mu", "Coulomb friction coefficient (a pair: sqrt(mu1 mu2))", "default_friction", K_NUM, R_CLOSED, 0, 10, friction, TY_ALL),
    ATTR("mass", "mass = m", "mass, kg; negative: static, never moves", "the volume", K_NUM, R_MASS, VR_MASS_MIN, VR_MASS_MAX, mass, TY_ALL),
    ATTR("volume", "volume = v", "nominal volume, m^3: the mass when mass is not given", "1", K_NUM, R_CLOSED, VR_MASS_MIN, VR_MASS_MAX, volume, TY_ALL),
    ATTR("translate", "translate = (x,y,z)", "initial position of the modelling frame, m (replaces)", "(0,0,0)", K_VEC3, R_CLOSED, -VR_LENGTH_MAX, VR_LENGTH_MAX, translate, TY_ALL),
    ATTR("rotate", "rotate = (x,y,z) r", "initial rotation, r radians about the axis (x,y,z) (replaces)", "none", K_AXIS, R_ANY, 0, 0, rotate_axis, TY_ALL),
    ATTR("color", "color = (r,g,b)", "colour", "(255,0,0)", K_IVEC3, R_CLOSED, 0, 255, color, TY_ALL),
    ATTR("radius", "radius = r", "sphere radius, m", "1", K_NUM, R_CLOSED, VR_LENGTH_MIN, VR_LENGTH_MAX, radius, TY_SPHERE),
    ATTR("ures", "ures = u", "tessellation: longitude steps (sphere, superquadric)", "10", K_INT, R_CLOSED, 3, 1000, ures, TY_SPHERE | TY_SQ),
    ATTR("vres", "vres = v", "tessellation: latitude bands (sphere, superquadric)", "10", K_INT, R_CLOSED, 3, 1000, vres, TY_SPHERE | TY_SQ),
    ATTR("size", "size = (x,y,z)", "cube half-extents (\"radii\"), m", "(1,1,1)", K_VEC3, R_CLOSED, VR_LENGTH_MIN, VR_LENGTH_MAX, size, TY_CUBE),
    ATTR("exp1", "exp1 = e", "superquadric exponent e1 (Barr 1981)", "1", K_NUM, R_CLOSED, 0.05, 2, exp1, TY_SQ),
    ATTR("exp2", "exp2 = e", "superquadric exponent e2 (Barr 1981)", "1", K_NUM, R_CLOSED, 0.05, 2, exp2, TY_SQ),
    ATTR("a1", "a1 = a", "superquadric x radius, m", "1", K_NUM, R_CLOSED, VR_LENGTH_MIN, VR_LENGTH_MAX, a1, TY_SQ),
    ATTR("a2", "a2 = a", "superquadric y radius, m", "1", K_NUM, R_CLOSED, VR_LENGTH_MIN, VR_LENGTH_MAX, a2, TY_SQ),
    ATTR("a3", "a3 = a", "superquadric z radius, m", "1", K_NUM, R_CLOSED, VR_LENGTH_MIN, VR_LENGTH_MAX, a3, TY_SQ),
    {"file", "file = path.off", "polyhedron: its OFF file (the rest of the line)", NULL, G_ATTR, F_ASSIGN, K_TEXT,
     R_ANY, 0, VR_PATH_MAX - 1, 0, NULL, T_OBJECT, offsetof(vrObjectDef, file), TY_POLY, run_attr},
    ATTR("scale", "scale = s | (sx,sy,sz)", "polyhedron: its OFF vertices times s (each axis)", "1", K_SCALE, R_CLOSED, VR_SCALE_MIN, VR_SCALE_MAX, scale, TY_POLY),
    ATTR("real", "real = 0|1", "1: a model of a real object (see_through draws it differently)", "0", K_INT, R_CLOSED, 0, 1, real, TY_ALL),

    VERB("read", "read FILE", "read commands from FILE (relative to the file that reads it)", G_SYSTEM, F_PATH, R_ANY, 0, 0, run_read),
    VERB("display", "display", "open the display and draw the current frame", G_SYSTEM, F_BARE, R_ANY, 0, 0, run_display),
    VERB("window", "window", "open the live window (needs $DISPLAY) and show the current frame", G_SYSTEM, F_BARE, R_ANY, 0, 0, run_window),
    VERB("reset", "reset", "put the head pose (eye, look, up) back to its default", G_SYSTEM, F_BARE, R_ANY, 0, 0, run_reset),
    VERB("restart", "restart", "remove all objects; reset time, frames and statistics (settings stay)", G_SYSTEM, F_BARE, R_ANY, 0, 0, run_restart),
    VERB("start", "start", "start time (a script: until all rest or max_frames frames)", G_SYSTEM, F_BARE, R_ANY, 0, 0, run_start),
    VERB("stop", "stop", "stop time", G_SYSTEM, F_BARE, R_ANY, 0, 0, run_stop),
    VERB("step", "step [n]", "advance n frames (default 1)", G_SYSTEM, F_COUNT, R_CLOSED, 1, 1e9, run_step),
    VERB("refresh", "refresh", "draw the current frame again, without advancing", G_SYSTEM, F_BARE, R_ANY, 0, 0, run_display),
    VERB("help", "help [NAME]", "list the commands, or describe one", G_SYSTEM, F_TOPIC, R_ANY, 0, 0, sh_print_help),
    VERB("quit", "quit", "leave vroc", G_SYSTEM, F_BARE, R_ANY, 0, 0, run_quit),
    VERB("exit", "exit", "leave vroc (the same as quit)", G_SYSTEM, F_BARE, R_ANY, 0, 0, run_quit),
    SETTING("time_step", "time_step = t", "frame time step, s (0 halts time)", "0.1", G_SYSTEM, K_NUM, R_CLOSED, 0, VR_TIME_MAX, time_step),
    SETTING("collision_dist", "collision_dist = d", "collision distance: the contact envelope, m (bodies rest min(d, 1 mm) apart)", "0.25", G_SYSTEM, K_NUM, R_CLOSED, VR_LENGTH_MIN, VR_LENGTH_MAX, collision_dist),
    SETTING("internal_step", "internal_step = i", "force the internal step, s (0: automatic)", "0", G_SYSTEM, K_NUM, R_CLOSED, 0, VR_TIME_MAX, internal_step),
    SETTING("max_linear", "max_linear = v", "maximum linear speed, m/s", "8", G_SYSTEM, K_NUM, R_GT, 0, VR_SPEED_MAX, max_linear),
    SETTING("max_angular", "max_angular = v", "maximum angular speed, rad/s", "4", G_SYSTEM, K_NUM, R_GT, 0, VR_SPEED_MAX, max_angular),
    SETTING("force", "force = (x,y,z) m", "global force: direction, and magnitude m/s^2 on every dynamic object", "(0,0,-1) 0", G_SYSTEM, K_AXIS, R_CLOSED, 0, VR_ACCEL_MAX, force_dir),
    VERB("gravity", "gravity", "the same as force = (0,0,-1) 9.8", G_SYSTEM, F_BARE, R_ANY, 0, 0, run_gravity),
    TEXT_SETTING("collision_sound", "collision_sound = s", "sound of collisions: a sound file or a built-in (the rest of the line)", "bounce", G_SYSTEM, K_TEXT, 1, 255, collision_sound),
    SETTING("collision_vol", "collision_vol = v", "volume of the collision sound", "1", G_SYSTEM, K_NUM, R_CLOSED, 0, 1, collision_vol),
    SETTING("default_friction", "default_friction = mu", "friction of the objects created after it", "0", G_SYSTEM, K_NUM, R_CLOSED, 0, 10, default_friction),
    SETTING("default_elasticity", "default_elasticity = e", "elasticity of the objects created after it", "1", G_SYSTEM, K_NUM, R_CLOSED, 0, 1, default_elasticity),
    SETTING("rest_speed", "rest_speed = v", "a body with friction slower than this for 0.5 s rests, m/s (0: only a still one)", "0.05", G_EXT, K_NUM, R_CLOSED, 0, 10, rest_speed),
    SETTING("contact_step", "contact_step = s", "longest step between island steps, s (contacts solved together)", "0.0041667", G_EXT, K_NUM, R_CLOSED, 1e-5, 0.1, contact_step),

    VERB("save", "save FILE", "write the whole state as a script a fresh vroc reads to go on bit for bit", G_EXT, F_PATH, R_ANY, 0, 0, run_save),
    VERB("state", "state WORD ...", "a saved file's line: one piece of a run's state (written by save)", G_EXT, F_PATH, R_ANY, 0, 0, run_state),
    VERB("dump", "dump", "print every object's state (one CSV line each, by name)", G_EXT, F_BARE, R_ANY, 0, 0, run_dump),
    VERB("stats", "stats", "print the statistics (one line of key=value)", G_EXT, F_BARE, R_ANY, 0, 0, run_stats),
    VERB("show", "show NAME", "print the attributes of object NAME (show head, hand, panel: the trackers, the tool panel)", G_EXT, F_NAME, R_ANY, 0, 0, run_show),
    VERB("delete", "delete NAME", "remove object NAME", G_EXT, F_NAME, R_ANY, 0, 0, run_delete),
    {"frames", "frames = DIR", "write each frame's image pair into DIR (empty: stop writing)", "frames", G_EXT, F_ASSIGN,
     K_TEXT, R_ANY, 0, VR_PATH_MAX - 1, 1, NULL, T_NONE, 0, 0, run_frames},
    {"frames_format", "frames_format = ppm|png", "the files frames are written as", "ppm", G_EXT, F_ASSIGN,
     K_CHOICE, R_ANY, 0, 0, 0, frame_formats, T_NONE, 0, 0, run_frames_format},
    SETTING("max_frames", "max_frames = n", "a script's start stops after n frames", "600", G_EXT, K_INT, R_CLOSED, 0, 1e9, max_frames),
    SETTING("heap", "heap = 0|1", "1: the scheduling heap; 0: every pair at every internal step", "1", G_EXT, K_INT, R_CLOSED, 0, 1, heap),
    SETTING("keep_looks", "keep_looks = 0|1", "1: looks past an event at pairs it does not change stand; 0: made again",
            "1", G_EXT, K_INT, R_CLOSED, 0, 1, keep_looks),
    {"broadphase", "broadphase = sweep|tree", "how the pairs whose boxes meet are found: sorted sweep or box trees",
     "tree", G_EXT, F_ASSIGN, K_CHOICE, R_ANY, 0, 0, 0, broadphases, T_SETTINGS, offsetof(vrSettings, broadphase), 0,
     run_setting},
    SETTING("gps", "gps = n", "worker processes (0: serial)", "0", G_EXT, K_INT, R_CLOSED, 0, 64, gps),
    {"distribution", "distribution = round_robin|improved", "how pairs are dealt to the workers", "round_robin", G_EXT,
     F_ASSIGN, K_CHOICE, R_ANY, 0, 0, 0, distributions, T_SETTINGS, offsetof(vrSettings, distribution), 0, run_setting},
    TEXT_SETTING("lcm_url", "lcm_url = URL", "LCM transport of the workers", "udpm://239.255.76.67:7667?ttl=0", G_EXT, K_WORD, 0, 255, lcm_url),
    {"seed", "seed = n", "seed of the stream that random draws from", "0", G_EXT, F_ASSIGN, K_UINT64, R_ANY, 0, 0, 0, NULL,
     T_SETTINGS, offsetof(vrSettings, seed), 0, run_setting},
    VERB("random", "random N", "add N random dynamic objects r0, r1, ... (thesis table 5.6)", G_EXT, F_INT, R_CLOSED, 1, 10000, run_random),
    SETTING("room", "room = s", "put later random objects in a closed room of side s, m (0: none)", "0", G_EXT, K_NUM, R_CLOSED, 0, VR_LENGTH_MAX, room),

    SETTING("sound_min_speed", "sound_min_speed = v", "the slowest impact that makes a sound, m/s", "0.5", G_EXT, K_NUM, R_CLOSED, 0, VR_SPEED_MAX, sound_min_speed),
    {"sound_log", "sound_log = FILE", "write collision sound events into FILE (empty: stop writing)", "none", G_EXT, F_ASSIGN,
     K_TEXT, R_ANY, 0, VR_PATH_MAX - 1, 1, NULL, T_NONE, 0, 0, run_sound_log},
    {"trackers", "trackers = URL", "take live head and hand samples from LCM at URL (empty: stop)", "none", G_EXT, F_ASSIGN,
     K_WORD, R_ANY, 0, 255, 1, NULL, T_NONE, 0, 0, run_trackers},
    SETTING("select", "select = 0|1", "1: the hand's trigger grabs and throws objects; 0: it flies the view", "0", G_EXT, K_INT, R_CLOSED, 0, 1, select),
    SETTING("grab_reach", "grab_reach = m", "the trigger grabs an object this near its surface, m", "0.1", G_EXT, K_NUM, R_CLOSED, 0, 10, grab_reach),
    SETTING("fly_speed", "fly_speed = v", "the trigger flies the view this fast along the hand, m/s (select = 0)", "1", G_EXT, K_NUM, R_CLOSED, 0, VR_SPEED_MAX, fly_speed),
    SETTING("hand_filter", "hand_filter = 0|1", "1: smooth the hand with the 1-euro filter (a throw takes its motion)", "0", G_EXT, K_INT, R_CLOSED, 0, 1, hand_filter),
    SETTING("hand_min_cutoff", "hand_min_cutoff = f", "the hand filter's cutoff at rest, Hz", "1", G_EXT, K_NUM, R_CLOSED, 1e-3, 1e3, hand_min_cutoff),
    SETTING("hand_beta", "hand_beta = b", "how fast the hand filter's cutoff rises with speed, s/m", "10", G_EXT, K_NUM, R_CLOSED, 0, 1e6, hand_beta),
    SETTING("panel", "panel = 0|1", "1: the virtual tool panel is drawn and the hand works it (show panel)", "0", G_EXT, K_INT, R_CLOSED, 0, 1, panel),
    VERB("track", "track FILE", "play a track file (head and hand samples) from now, in simulation time", G_EXT, F_PATH, R_ANY, 0, 0, run_track),

    VIEW("resolution", "resolution = (w,h)", "frame size, pixels", "(640,512)", K_IVEC2, R_CLOSED, 16, 8192, width),
    VIEW("eye", "eye = (x,y,z)", "head (eye) position, m", "(0,-8,3)", K_VEC3, R_CLOSED, -VR_LENGTH_MAX, VR_LENGTH_MAX, eye),
    VIEW("look", "look = (x,y,z)", "the point looked at, m", "(0,0,1)", K_VEC3, R_CLOSED, -VR_LENGTH_MAX, VR_LENGTH_MAX, look),
    VIEW("up", "up = (x,y,z)", "the head's up direction", "(0,0,1)", K_VEC3, R_NONZERO, 0, 0, up),
    VIEW("ipd", "ipd = m", "distance between the eyes, m", "0.064", K_NUM, R_CLOSED, 0, VR_LENGTH_MAX, ipd),
    VIEW("focal", "focal = m", "distance where the eyes converge, m (0: |look - eye|)", "0", K_NUM, R_CLOSED, 0, VR_LENGTH_MAX, focal),
    VIEW("fov", "fov = degrees", "vertical field of view", "45", K_NUM, R_CLOSED, 10, 120, fov),
    {"window_mode", "window_mode = mono|side|anaglyph", "the window: one view, the eyes side by side, or red-cyan", "mono", G_VIEW, F_ASSIGN,
     K_CHOICE, R_ANY, 0, 0, 0, window_modes, T_NONE, 0, 0, run_window_mode},
    VIEW("see_through", "see_through = 0|1|2", "real objects: 0 solid, 1 wireframe, 2 not drawn", "0", K_INT, R_CLOSED, 0, 2, see_through),
};
const int sh_ncommands = (int)(sizeof sh_commands / sizeof sh_commands[0]);

const Command *sh_find_command(const char *name, size_t len)
{
    int i;
    for (i = 0; i < sh_ncommands; i++)
        if (strlen(sh_commands[i].name) == len && memcmp(sh_commands[i].name, name, len) == 0) return &sh_commands[i];
    return NULL;
}

const char *const *sh_command_names(void)
{
    static const char *names[sizeof sh_commands / sizeof sh_commands[0] + 1];
    int i;
    if (!names[0])
        for (i = 0; i < sh_ncommands; i++) names[i] = sh_commands[i].name;
    return names;
}

/* ---- ranges ------------------------------------------------------------------ */

/* %g without the exponent's "+0": 1e9, not 1e+09 */
static void short_number(char *buf, size_t n, double x)
{
    char *e;
    snprintf(buf, n, "%g", x);
    e = strchr(buf, 'e');
    if (e) {
        char *d = e + 1, *s = e + 1;
        if (*s == '+') s++;
        if (*s == '-') *d++ = *s++;
        while (*s == '0' && s[1]) s++;
        memmove(d, s, strlen(s) + 1);
    }
}

static int integer_kind(const Command *c)
{
    return c->kind == K_INT || c->kind == K_IVEC3 || c->kind == K_IVEC2 || c->form == F_COUNT || c->form == F_INT;
}

/* "a or b", "a, b or c" */
static void choice_list(const Command *c, char *buf, size_t n)
{
    size_t used = 0;
    int i;
    buf[0] = '\0';
    for (i = 0; c->choices[i] && used < n; i++) {
        const char *sep = i == 0 ? "" : c->choices[i + 1] ? ", " : " or ";
        used += (size_t)snprintf(buf + used, n - used, "%s%s", sep, c->choices[i]);
    }
}

void sh_range_text(const Command *c, char *buf, size_t n)
{
    char lo[32], hi[32], upper[48] = "";
    const char *what = integer_kind(c) ? "integer " : "";
    short_number(lo, sizeof lo, c->lo);
    short_number(hi, sizeof hi, c->hi);
    if (c->kind == K_UINT64) {
        snprintf(buf, n, "integer 0..18446744073709551615");
        return;
    }
    if (c->kind == K_CHOICE) {
        choice_list(c, buf, n);
        return;
    }
    if (c->hi > 0 && c->range != R_MASS) snprintf(upper, sizeof upper, ", at most %s", hi);
    switch (c->range) {
    case R_ANY: snprintf(buf, n, "%s", c->kind == K_TEXT || c->kind == K_WORD || c->kind == K_NONE ? "" : "finite"); break;
    case R_NONZERO: snprintf(buf, n, "non-zero"); break;
    case R_MASS: snprintf(buf, n, "< 0 (static) or %s..%s", lo, hi); break;
    case R_GT: snprintf(buf, n, "%s> %s%s", what, lo, upper); break;
    case R_GE: snprintf(buf, n, "%s>= %s%s", what, lo, upper); break;
    case R_CLOSED: snprintf(buf, n, "%s%s..%s", what, lo, hi); break;
    }
}

static int in_range(const Command *c, double x)
{
    if (!isfinite(x)) return 0;
    if (integer_kind(c) && x != floor(x)) return 0;
    switch (c->range) {
    case R_ANY: return 1;
    case R_NONZERO: return x != 0;
    case R_MASS: return x < 0 || (x >= c->lo && x <= c->hi);
    case R_GT: return x > c->lo && x <= c->hi;
    case R_GE:
    case R_CLOSED: return x >= c->lo && x <= c->hi;
    }
    return 0;
}

static int range_error(const Command *c, const char *part, double x, char *err, size_t n)
{
    char r[96], g[32];
    sh_range_text(c, r, sizeof r);
    vrFormatDouble(g, x);
    snprintf(err, n, "%s%s must be %s%s (got %s)", part, c->name, integer_kind(c) ? "an " : "", r, g);
    return -1;
}

static int check_numbers(const Command *c, const double *v, int count, char *err, size_t n)
{
    int i;
    if (c->range == R_NONZERO && count == 3) {
        if (v[0] == 0 && v[1] == 0 && v[2] == 0) {
            snprintf(err, n, "%s must be a non-zero vector", c->name);
            return -1;
        }
        return 0;
    }
    for (i = 0; i < count; i++)
        if (!in_range(c, v[i])) return range_error(c, count > 1 ? "each component of " : "", v[i], err, n);
    return 0;
}

/* ---- parsing ----------------------------------------------------------------- */

static int text_value(Lexer *lx, const Command *c, Stmt *st, char *err, size_t n)
{
    if (c->kind == K_WORD) lx_word(lx, &st->text, &st->textlen);
    else lx_rest(lx, &st->text, &st->textlen);
    if (st->textlen == 0 && !c->allow_empty) {
        snprintf(err, n, "'%s' needs a value (%s)", c->name, c->syntax);
        return -1;
    }
    if (st->textlen > (size_t)c->hi) {
        snprintf(err, n, "the value of '%s' is too long (%lu bytes, at most %d)", c->name,
                 (unsigned long)st->textlen, (int)c->hi);
        return -1;
    }
    return 0;
}

static int choice_value(Lexer *lx, const Command *c, Stmt *st, char *err, size_t n)
{
    char g[80], list[160];
    lx_word(lx, &st->text, &st->textlen);
    for (st->choice = 0; c->choices[st->choice]; st->choice++)
        if (strlen(c->choices[st->choice]) == st->textlen
            && memcmp(c->choices[st->choice], st->text, st->textlen) == 0)
            return 0;
    lx_quote(g, sizeof g, st->text, st->textlen);
    choice_list(c, list, sizeof list);
    snprintf(err, n, "%s must be %s (got %s)", c->name, list, g);
    return -1;
}

static int axis_value(Lexer *lx, const Command *c, Stmt *st, char *err, size_t n)
{
    if (lx_vector(lx, c->name, st->v, 3, err, n) != 0) return -1;
    if (st->v[0] == 0 && st->v[1] == 0 && st->v[2] == 0) {
        snprintf(err, n, "the vector of '%s' must be non-zero", c->name);
        return -1;
    }
    if (lx_at_end(lx)) {   /* the number after the vector forgotten: say which */
        snprintf(err, n, "'%s' needs its number after the vector (%s)", c->name, c->syntax);
        return -1;
    }
    if (lx_number(lx, c->name, &st->v[3], err, n) != 0) return -1;
    return in_range(c, st->v[3]) ? 0 : range_error(c, "the magnitude of ", st->v[3], err, n);
}

/* one number for every axis, or a vector */
static int scale_value(Lexer *lx, const Command *c, Stmt *st, char *err, size_t n)
{
    lx_skip_blanks(lx);
    if (lx->p < lx->end && *lx->p == '(') {
        if (lx_vector(lx, c->name, st->v, 3, err, n) != 0) return -1;
    } else {
        if (lx_number(lx, c->name, st->v, err, n) != 0) return -1;
        st->v[1] = st->v[2] = st->v[0];
    }
    return check_numbers(c, st->v, 3, err, n);
}

static int parse_value(Lexer *lx, const Command *c, Stmt *st, char *err, size_t n)
{
    switch (c->kind) {
    case K_NUM:
    case K_INT:
        if (lx_number(lx, c->name, st->v, err, n) != 0) return -1;
        return check_numbers(c, st->v, 1, err, n);
    case K_VEC3:
    case K_IVEC3:
        if (lx_vector(lx, c->name, st->v, 3, err, n) != 0) return -1;
        return check_numbers(c, st->v, 3, err, n);
    case K_IVEC2:
        if (lx_vector(lx, c->name, st->v, 2, err, n) != 0) return -1;
        return check_numbers(c, st->v, 2, err, n);
    case K_AXIS: return axis_value(lx, c, st, err, n);
    case K_SCALE: return scale_value(lx, c, st, err, n);
    case K_TEXT:
    case K_WORD: return text_value(lx, c, st, err, n);
    case K_CHOICE: return choice_value(lx, c, st, err, n);
    case K_UINT64: return lx_uint64(lx, c->name, &st->u, err, n);
    case K_NONE: break;
    }
    return 0;
}

static int expect_assign(Lexer *lx, const Command *c, char *err, size_t n)
{
    char g[80];
    if (lx_accept(lx, '=')) return 0;
    if (lx_at_end(lx)) snprintf(err, n, "'%s' needs a value: %s", c->name, c->syntax);
    else {
        lx_quote(g, sizeof g, lx->p, lx_token_len(lx));
        snprintf(err, n, "expected '=' after '%s', got %s (%s)", c->name, g, c->syntax);
    }
    return -1;
}

static int parse_args(Lexer *lx, const Command *c, Stmt *st, char *err, size_t n)
{
    switch (c->form) {
    case F_BARE: return 0;
    case F_COUNT:
        if (lx_at_end(lx)) return 0;
        st->has_value = 1;
        /* fall through */
    case F_INT:
        if (lx_number(lx, c->name, st->v, err, n) != 0) return -1;
        return check_numbers(c, st->v, 1, err, n);
    case F_NAME: return lx_name(lx, c->name, st->name, sizeof st->name, err, n);
    case F_TOPIC:
        lx_word(lx, &st->text, &st->textlen);
        st->has_value = st->textlen > 0;
        return 0;
    case F_PATH:
        lx_rest(lx, &st->text, &st->textlen);
        if (st->textlen > 0) return 0;
        snprintf(err, n, "'%s' needs a file name", c->name);
        return -1;
    case F_ASSIGN:
        if (expect_assign(lx, c, err, n) != 0) return -1;
        return parse_value(lx, c, st, err, n);
    }
    return 0;
}

static int unknown_word(Lexer *lx, size_t len, char *err, size_t n)
{
    const char *word = lx->p, *near;
    char q[80];
    int is_attr;
    lx_quote(q, sizeof q, word, len);
    lx->p += len;
    is_attr = lx_accept(lx, '=');
    near = lx_suggest(word, len, sh_command_names(), sh_ncommands);
    if (near) snprintf(err, n, "unknown %s %s (did you mean '%s'?)", is_attr ? "attribute" : "command", q, near);
    else snprintf(err, n, "unknown %s %s (type help for the list)", is_attr ? "attribute" : "command", q);
    return -1;
}

static int parse_statement(Lexer *lx, Stmt *st, char *err, size_t n)
{
    size_t len = lx_token_len(lx);
    char q[80];
    const Command *c = sh_find_command(lx->p, len);
    memset(st, 0, sizeof *st);
    if (!c) return unknown_word(lx, len, err, n);
    lx->p += len;
    st->cmd = c;
    if (parse_args(lx, c, st, err, n) != 0) return -1;
    if (lx_at_end(lx)) return 0;
    lx_quote(q, sizeof q, lx->p, (size_t)(lx->end - lx->p));
    snprintf(err, n, "unexpected %s after the statement (%s)", q, c->syntax);
    return -1;
}

int sh_exec_line(Shell *sh, char *line, size_t len)
{
    char err[SH_ERR_MAX], *text;
    size_t textlen;
    Lexer lx;
    Stmt st;
    err[0] = '\0';
    if (lx_clean(line, len, &text, &textlen, err, sizeof err) != 0) goto fail;
    if (textlen == 0) return 0;
    lx_init(&lx, text, textlen);
    if (parse_statement(&lx, &st, err, sizeof err) != 0) goto fail;
    if (st.cmd->run(sh, &st, err, sizeof err) != 0) goto fail;
    return 0;
fail:
    sh_error(sh, "%s", err);
    return -1;
}
