/* test_render.c — the display (SPEC 4): stereo geometry, lighting, depth,
 * see-through drawing, PPM output, errors, and lazy loading of OSMesa.
 *
 * Scenes are built through the public API and drawn with vrDisplay_Render;
 * pixels are read back with vrDisplay_Pixels.  The test view looks along +y
 * from (0,-5,0) at the origin, z up, so "distance from the head" is y + 5.
 */
#define _DEFAULT_SOURCE 1   /* setenv, mkdtemp */
#include <errno.h>
#include <png.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "test.h"
#include "vroc.h"
#include "scene.h"

#define TEST_PI 3.14159265358979323846

static char err[512];

/* ---- scenes -------------------------------------------------------------- */
static vrView test_view(int width, int height)
{
    vrView v = vrView_Default();
    v.width = width, v.height = height;
    v.eye[0] = 0, v.eye[1] = -5, v.eye[2] = 0;
    v.look[0] = v.look[1] = v.look[2] = 0;
    v.up[0] = 0, v.up[1] = 0, v.up[2] = 1;
    return v;
}

/* a box with half extents h centred at c, static, of colour rgb; real: see-through */
static vrObjectId add_box(vrWorld *w, const char *name, const double c[3], const double h[3],
                          int r, int g, int b, int real)
{
    vrObjectDef d = vrObjectDef_Default(VR_CUBE);
    int i;
    for (i = 0; i < 3; i++) d.translate[i] = c[i], d.size[i] = h[i];
    d.color[0] = r, d.color[1] = g, d.color[2] = b;
    d.mass = -1, d.mass_set = 1;
    d.real = real;
    return vrScene_Add(w, name, VR_CUBE, &d);
}

static vrObjectId add_sphere(vrWorld *w, const char *name, const double c[3], double radius,
                             int r, int g, int b)
{
    vrObjectDef d = vrObjectDef_Default(VR_SPHERE);
    int i;
    for (i = 0; i < 3; i++) d.translate[i] = c[i];
    d.radius = radius;
    d.color[0] = r, d.color[1] = g, d.color[2] = b;
    return vrScene_Add(w, name, VR_SPHERE, &d);
}

/* ---- pixels -------------------------------------------------------------- */
typedef struct Region {
    long count;
    double cx, cy;              /* centroid, pixel centres at +0.5 */
    int x0, y0, x1, y1;         /* bounding box, inclusive */
} Region;

static int near_rgb(const unsigned char *p, int r, int g, int b, int tol)
{
    return abs(p[0] - r) <= tol && abs(p[1] - g) <= tol && abs(p[2] - b) <= tol;
}

/* the pixels of one eye within tol of colour (r,g,b) */
static Region find_color(const vrDisplay *d, int eye, int r, int g, int b, int tol)
{
    Region reg = {0, 0, 0, 1 << 30, 1 << 30, -1, -1};
    int w, h, x, y;
    const unsigned char *px = vrDisplay_Pixels(d, eye, &w, &h);
    for (y = 0; px && y < h; y++)
        for (x = 0; x < w; x++) {
            if (!near_rgb(px + 3 * ((size_t)y * w + x), r, g, b, tol)) continue;
            reg.count++, reg.cx += x + 0.5, reg.cy += y + 0.5;
            if (x < reg.x0) reg.x0 = x;
            if (y < reg.y0) reg.y0 = y;
            if (x > reg.x1) reg.x1 = x;
            if (y > reg.y1) reg.y1 = y;
        }
    if (reg.count) reg.cx /= reg.count, reg.cy /= reg.count;
    return reg;
}

static const unsigned char *pixel(const vrDisplay *d, int eye, int x, int y)
{
    int w, h;
    const unsigned char *px = vrDisplay_Pixels(d, eye, &w, &h);
    return px + 3 * ((size_t)y * w + x);
}

/* a world, a view and (once shown) a display: what every test draws with */
typedef struct Scene {
    vrWorld *w;
    vrView v;
    vrDisplay *d;
} Scene;

static Scene scene(int width, int height)
{
    Scene s;
    s.w = vrWorld_Create();
    s.v = test_view(width, height);
    s.d = NULL;
    return s;
}

/* draws the scene (opening the display the first time); -1 and a message */
static int show(Scene *s)
{
    if (!s->d && vrDisplay_Open(&s->d, err, sizeof err)) {
        printf("    vrDisplay_Open: %s\n", err);
        return -1;
    }
    if (vrDisplay_Render(s->d, s->w, &s->v, err, sizeof err)) {
        printf("    vrDisplay_Render: %s\n", err);
        return -1;
    }
    return 0;
}

static void done(Scene *s)
{
    vrDisplay_Close(s->d);
    vrWorld_Destroy(s->w);
}

static int maps_contain(const char *what)
{
    char line[1024];
    int found = 0;
    FILE *f = fopen("/proc/self/maps", "r");
    while (f && fgets(line, sizeof line, f))
        if (strstr(line, what)) found = 1;
    if (f) fclose(f);
    return found;
}

/* ---- lazy loading (these run first: the module stays loaded once opened) -- */
/* exit status of a forked child running fn (so the parent's state is untouched) */
static int in_child(int (*fn)(void))
{
    int status = 0;
    pid_t pid;
    fflush(stdout);
    pid = fork();
    if (pid == 0) _exit(fn());
    if (pid < 0 || waitpid(pid, &status, 0) != pid) return -1;
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

enum { MAPPED_BEFORE = 10, NOT_SEEN_AFTER, SETUP_FAILED };

static int world_without_display(void)
{
    vrWorld *w = vrWorld_Create();
    double c[3] = {0, 0, 1};
    vrDisplay *d = NULL;
    FILE *null = fopen("/dev/null", "w");
    int before;
    add_sphere(w, "ball", c, 0.5, 255, 0, 0);
    if (!null || vrWorld_Step(w, 3, err, sizeof err) || vrWorld_WriteDump(w, null)) return SETUP_FAILED;
    fclose(null);
    before = maps_contain("libOSMesa");
    /* the check itself must be able to see OSMesa once a display opens */
    if (vrDisplay_Open(&d, err, sizeof err)) return SETUP_FAILED;
    return before ? MAPPED_BEFORE : maps_contain("libOSMesa") ? 0 : NOT_SEEN_AFTER;
}

static int test_world_without_display_does_not_load_osmesa(void)
{
    int r = in_child(world_without_display);
    ENSURE_MSG(r != MAPPED_BEFORE, "libOSMesa is mapped before any display was opened");
    ENSURE_MSG(r != NOT_SEEN_AFTER, "libOSMesa not seen in /proc/self/maps after vrDisplay_Open");
    ENSURE_MSG(r == 0, "child failed (exit status %d; %s)", r, r == SETUP_FAILED ? err : "crashed?");
    return 0;
}

static int open_missing_module(void)
{
    vrDisplay *d = NULL;
    setenv("VROC_RENDER_MODULE", "/nonexistent/vroc-render.so", 1);
    if (vrDisplay_Open(&d, err, sizeof err) == 0) return 1;
    return d == NULL && strstr(err, "render module") && strstr(err, "/nonexistent") ? 0 : 2;
}

static int test_missing_render_module_is_a_clear_error(void)
{
    ENSURE_NEAR(in_child(open_missing_module), 0, 0);
    return 0;
}

/* ---- stereo geometry ----------------------------------------------------- */
/* SPEC 4: horizontal offset from the image centre, in pixels, of a point on
 * the head axis at distance z, for the left eye (the right eye: opposite).
 * Off-axis frusta converging at `focal`: x_ndc = (ipd/2)(1/z - 1/focal) /
 * (tan(fov/2) aspect), and W/2 pixels per unit of x_ndc. */
static double predicted_offset(double ipd, double fov, int height, double z, double focal)
{
    return (ipd / 2) * (1 / z - 1 / focal) * height / (2 * tan(fov * TEST_PI / 360.0));
}

/* A thin panel whose front face (toward the head) is at distance z on the
 * axis, about 15 pixels half-size: its fully lit pixels are the projection
 * of a centred square.  Left and right centroids, relative to the centre. */
static int axis_offsets(double z, double ipd, double focal, double out[4])
{
    Scene s = scene(320, 256);
    double half[3] = {0.1 * z, 0.001, 0.1 * z}, c[3] = {0, -5 + z + 0.001, 0};
    Region L, R;
    s.v.ipd = ipd, s.v.focal = focal;
    if (add_box(s.w, "panel", c, half, 200, 100, 50, 0) == VR_NO_OBJECT || show(&s)) return -1;
    L = find_color(s.d, 0, 200, 100, 50, 1);
    R = find_color(s.d, 1, 200, 100, 50, 1);
    done(&s);
    if (L.count < 100 || R.count < 100) return -1;
    out[0] = L.cx - 160, out[1] = L.cy - 128, out[2] = R.cx - 160, out[3] = R.cy - 128;
    return 0;
}

static int check_axis_disparity(double z, double ipd, double focal)
{
    double off[4], expect = predicted_offset(ipd, 45, 256, z, focal > 0 ? focal : 5.0);
    ENSURE(axis_offsets(z, ipd, focal, off) == 0);
    ENSURE_NEAR(off[1], 0, 0.5);
    ENSURE_NEAR(off[3], 0, 0.5);
    ENSURE_NEAR(off[0], expect, 0.5);
    ENSURE_NEAR(off[2], -expect, 0.5);
    return 0;
}

/* ipd 0.3 m makes the offsets large against rasterisation's half pixel */
static int test_near_point_on_axis_has_crossed_disparity_of_predicted_size(void)
{
    ENSURE(predicted_offset(0.3, 45, 256, 2, 5) > 13);     /* left eye: further right */
    return check_axis_disparity(2.0, 0.3, 0);
}

static int test_far_point_on_axis_has_uncrossed_disparity(void)
{
    ENSURE(predicted_offset(0.3, 45, 256, 20, 5) < -4);
    return check_axis_disparity(20.0, 0.3, 0);
}

static int test_point_at_focal_distance_has_zero_disparity(void)
{
    return check_axis_disparity(5.0, 0.3, 0);
}

static int test_focal_setting_moves_the_zero_disparity_plane(void)
{
    double off[4];
    ENSURE(axis_offsets(2.0, 0.3, 2.0, off) == 0);
    ENSURE_NEAR(off[0], 0, 0.5);
    ENSURE_NEAR(off[2], 0, 0.5);
    return check_axis_disparity(3.0, 0.3, 2.0);
}

static int test_image_is_upright_and_not_mirrored(void)
{
    Scene s = scene(160, 128);
    double h[3] = {0.2, 0.2, 0.2}, up[3] = {0, 0, 1}, right[3] = {1.5, 0, 0};
    Region top, side;
    ENSURE(add_box(s.w, "up", up, h, 255, 0, 0, 0) != VR_NO_OBJECT);       /* +z: up */
    ENSURE(add_box(s.w, "right", right, h, 0, 255, 0, 0) != VR_NO_OBJECT); /* +x: right of +y */
    ENSURE(show(&s) == 0);
    top = find_color(s.d, 0, 255, 0, 0, 1);
    side = find_color(s.d, 0, 0, 255, 0, 1);
    done(&s);
    ENSURE(top.count > 50 && side.count > 50);
    ENSURE_MSG(top.cy < 50 && fabs(top.cx - 80) < 2, "up box at %.1f,%.1f", top.cx, top.cy);
    ENSURE_MSG(side.cx > 110 && fabs(side.cy - 64) < 2, "right box at %.1f,%.1f", side.cx, side.cy);
    return 0;
}

/* ---- colour and lighting ------------------------------------------------- */
/* the centre pixel of a 2 m box at the origin turned `angle` about z (up),
 * seen with both eyes on the axis (ipd 0) */
static int centre_color(double angle, int r, int g, int b, unsigned char out[3])
{
    Scene s = scene(160, 128);
    double half[3] = {1, 1, 1}, c[3] = {0, 0, 0};
    vrObjectId id = add_box(s.w, "box", c, half, r, g, b, 0);
    vrObjectDef def;
    const unsigned char *p;
    if (id == VR_NO_OBJECT) return -1;
    vrWorld_GetObjectDef(s.w, id, &def);
    def.rotate_axis[0] = 0, def.rotate_axis[1] = 0, def.rotate_axis[2] = 1;
    def.rotate_angle = angle, def.rotate_set = 1;
    s.v.ipd = 0;
    if (vrWorld_SetObjectDef(s.w, id, &def, err, sizeof err) || show(&s)) return -1;
    p = pixel(s.d, 0, 80, 64);      /* byte by byte: LTO's memcpy check sees a display without pixels */
    out[0] = p[0], out[1] = p[1], out[2] = p[2];
    done(&s);
    return 0;
}

static int test_face_toward_the_eye_shows_its_color(void)
{
    unsigned char px[3];
    ENSURE(centre_color(0, 200, 120, 40, px) == 0);
    ENSURE_MSG(near_rgb(px, 200, 120, 40, 1), "got %d %d %d", px[0], px[1], px[2]);
    return 0;
}

/* turned 30 degrees, the centre ray meets the face turned least */
static int test_tilted_face_is_lit_by_ambient_plus_diffuse_cosine(void)
{
    double theta = 30 * TEST_PI / 180, k = 0.2 + 0.8 * cos(theta);
    unsigned char px[3];
    ENSURE(centre_color(theta, 250, 100, 0, px) == 0);
    ENSURE_MSG(near_rgb(px, (int)(250 * k + 0.5), (int)(100 * k + 0.5), 0, 1),
               "got %d %d %d, expected %.1f %.1f 0", px[0], px[1], px[2], 250 * k, 100 * k);
    return 0;
}

static int test_sphere_is_smooth_shaded(void)
{
    Scene s = scene(160, 128);
    double c[3] = {0, 0, 0};
    int seen[256] = {0}, distinct = 0, x, y;
    ENSURE(add_sphere(s.w, "ball", c, 1.5, 0, 250, 0) != VR_NO_OBJECT);
    ENSURE(show(&s) == 0);
    for (y = 0; y < 128; y++)
        for (x = 0; x < 160; x++) seen[pixel(s.d, 0, x, y)[1]] = 1;
    done(&s);
    for (x = 1; x < 256; x++) distinct += seen[x];
    /* flat shading would give one shade per visible facet (~50); Gouraud a ramp */
    ENSURE_MSG(distinct > 100, "%d distinct shades", distinct);
    return 0;
}

/* ---- depth --------------------------------------------------------------- */
static int check_near_hides_far(int near_first)
{
    Scene s = scene(160, 128);
    double hn[3] = {0.3, 0.3, 0.3}, cn[3] = {0, -2, 0}, hf[3] = {1, 1, 1}, cf[3] = {0, 2, 0};
    const unsigned char *p;
    if (near_first) ENSURE(add_box(s.w, "near", cn, hn, 0, 0, 255, 0) != VR_NO_OBJECT);
    ENSURE(add_box(s.w, "far", cf, hf, 255, 255, 0, 0) != VR_NO_OBJECT);
    if (!near_first) ENSURE(add_box(s.w, "near", cn, hn, 0, 0, 255, 0) != VR_NO_OBJECT);
    ENSURE(show(&s) == 0);
    p = pixel(s.d, 0, 80, 64);
    ENSURE_MSG(near_rgb(p, 0, 0, 255, 1), "centre %d %d %d", p[0], p[1], p[2]);
    /* the far box is larger on screen: it shows around the near one */
    ENSURE(find_color(s.d, 0, 255, 255, 0, 1).count > 100);
    done(&s);
    return 0;
}

static int test_near_object_hides_far_one_in_either_order(void)
{
    return check_near_hides_far(0) || check_near_hides_far(1);
}

/* ---- see-through --------------------------------------------------------- */
/* a real box on the axis drawn with see_through = mode: the pixels of its
 * colour, and whether the centre is background */
static int real_box(int mode, Region *reg, int *centre_black)
{
    Scene s = scene(160, 128);
    double h[3] = {1, 1, 1}, c[3] = {0, 0, 0};
    s.v.see_through = mode;
    if (add_box(s.w, "table", c, h, 90, 200, 255, 1) == VR_NO_OBJECT || show(&s)) return -1;
    *reg = find_color(s.d, 0, 90, 200, 255, 1);
    *centre_black = near_rgb(pixel(s.d, 0, 80, 64), 0, 0, 0, 0);
    done(&s);
    return 0;
}

static int test_see_through_draws_real_objects_wire_hidden_or_solid(void)
{
    Region solid, wire, hidden;
    int black0, black1, black2;
    ENSURE(real_box(0, &solid, &black0) == 0);
    ENSURE(real_box(1, &wire, &black1) == 0);
    ENSURE(real_box(2, &hidden, &black2) == 0);
    ENSURE_MSG(solid.count > 1000 && !black0, "solid: %ld pixels, centre black %d", solid.count, black0);
    /* wireframe: edges in the object's colour around an empty inside */
    ENSURE_MSG(wire.count > 20 && wire.count < solid.count / 4 && black1,
               "wire: %ld pixels, centre black %d", wire.count, black1);
    ENSURE(wire.x0 >= solid.x0 - 1 && wire.x1 <= solid.x1 + 1);
    ENSURE(wire.y0 >= solid.y0 - 1 && wire.y1 <= solid.y1 + 1);
    ENSURE_MSG(hidden.count == 0 && black2, "hidden: %ld pixels", hidden.count);
    return 0;
}

static int test_real_object_hides_virtual_object_behind_it(void)
{
    Scene s = scene(160, 128);
    double hr[3] = {1, 0.1, 1}, cr[3] = {0, -1, 0}, cb[3] = {0, 1, 0}, cf[3] = {0.5, -3, 0};
    Region balls;
    s.v.see_through = 2;
    ENSURE(add_box(s.w, "wall", cr, hr, 90, 200, 255, 1) != VR_NO_OBJECT);
    ENSURE(add_sphere(s.w, "behind", cb, 0.5, 255, 0, 255) != VR_NO_OBJECT);
    ENSURE(add_sphere(s.w, "front", cf, 0.2, 255, 0, 255) != VR_NO_OBJECT);
    ENSURE(show(&s) == 0);
    /* as the real wall does in a see-through display: the ball behind it is
     * not seen, the one in front is, and the wall itself shows nothing */
    ENSURE(near_rgb(pixel(s.d, 0, 80, 64), 0, 0, 0, 0));
    ENSURE(find_color(s.d, 0, 90, 200, 255, 1).count == 0);
    balls = find_color(s.d, 0, 255, 0, 255, 60);
    ENSURE(balls.count > 50 && balls.x0 > 80);
    done(&s);
    return 0;
}

/* ---- output -------------------------------------------------------------- */
static unsigned char *read_file(const char *path, long *size)
{
    FILE *f = fopen(path, "rb");
    unsigned char *buf;
    if (!f) return NULL;
    fseek(f, 0, SEEK_END);
    *size = ftell(f);
    rewind(f);
    buf = malloc((size_t)*size + 1);
    if (buf && fread(buf, 1, (size_t)*size, f) != (size_t)*size) free(buf), buf = NULL;
    fclose(f);
    return buf;
}

/* dir/frame-NNNNNN-side.ppm holds exactly the header and the eye's pixels */
static int check_ppm(const vrDisplay *d, const char *dir, long frame, int eye, int width, int height)
{
    char header[64], path[256];
    long size;
    unsigned char *buf;
    int hl = snprintf(header, sizeof header, "P6\n%d %d\n255\n", width, height), w, h;
    const unsigned char *px = vrDisplay_Pixels(d, eye, &w, &h);
    snprintf(path, sizeof path, "%s/frame-%06ld-%s.ppm", dir, frame, eye ? "right" : "left");
    buf = read_file(path, &size);
    ENSURE_MSG(buf, "cannot read %s", path);
    ENSURE(size == hl + (long)width * height * 3);
    ENSURE(memcmp(buf, header, (size_t)hl) == 0);
    ENSURE(w == width && h == height && memcmp(buf + hl, px, (size_t)width * height * 3) == 0);
    free(buf);
    return 0;
}

static int make_tmpdir(char *dir, size_t len)
{
    snprintf(dir, len, "/tmp/vroc-render-XXXXXX");
    return mkdtemp(dir) ? 0 : -1;
}

static int remove_tree(const char *dir)
{
    char cmd[128];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
    return system(cmd);
}

static int test_frames_are_well_formed_ppm_in_a_created_folder(void)
{
    Scene s = scene(64, 40);        /* width != height: catches swapped fields */
    double h[3] = {0.5, 0.5, 0.5}, c[3] = {0, 0, 0};
    char dir[64], sub[128];
    ENSURE(make_tmpdir(dir, sizeof dir) == 0);
    snprintf(sub, sizeof sub, "%s/a/b/frames", dir);
    ENSURE(add_box(s.w, "box", c, h, 10, 20, 30, 0) != VR_NO_OBJECT);
    ENSURE(show(&s) == 0);
    ENSURE_MSG(vrDisplay_WriteFrames(s.d, sub, 7, VR_FRAMES_PPM, err, sizeof err) == 0, "%s", err);
    ENSURE(check_ppm(s.d, sub, 7, 0, 64, 40) == 0);
    ENSURE(check_ppm(s.d, sub, 7, 1, 64, 40) == 0);
    /* a new resolution: the next frames follow it */
    s.v.width = 48, s.v.height = 96;
    ENSURE(show(&s) == 0);
    ENSURE(vrDisplay_WriteFrames(s.d, sub, 1234567, VR_FRAMES_PPM, err, sizeof err) == 0);
    ENSURE(check_ppm(s.d, sub, 1234567, 0, 48, 96) == 0);
    ENSURE(near_rgb(pixel(s.d, 0, 24, 48), 10, 20, 30, 1));
    done(&s);
    ENSURE(remove_tree(dir) == 0);
    return 0;
}

/* frames_format = png: the file decodes (libpng, independently of the
 * writer's code path) to exactly the pixels rendered */
static int check_png(const vrDisplay *d, const char *dir, int eye, int width, int height)
{
    char path[256];
    png_image img;
    unsigned char *buf;
    int same;
    snprintf(path, sizeof path, "%s/frame-000003-%s.png", dir, eye ? "right" : "left");
    memset(&img, 0, sizeof img);
    img.version = PNG_IMAGE_VERSION;
    ENSURE_MSG(png_image_begin_read_from_file(&img, path), "%s: %s", path, img.message);
    ENSURE((int)img.width == width && (int)img.height == height);
    img.format = PNG_FORMAT_RGB;
    buf = malloc(PNG_IMAGE_SIZE(img));
    ENSURE(buf && png_image_finish_read(&img, NULL, buf, 0, NULL));
    same = memcmp(buf, vrDisplay_Pixels(d, eye, NULL, NULL), (size_t)width * height * 3) == 0;
    free(buf);
    ENSURE(same);
    return 0;
}

static int test_png_frames_decode_to_the_rendered_pixels(void)
{
    Scene s = scene(64, 40);
    double h[3] = {0.5, 0.5, 0.5}, c[3] = {0, 0, 0};
    char dir[64], ppm[128];
    struct stat sb;
    ENSURE(make_tmpdir(dir, sizeof dir) == 0);
    ENSURE(add_box(s.w, "box", c, h, 10, 20, 30, 0) != VR_NO_OBJECT);
    ENSURE(show(&s) == 0);
    ENSURE_MSG(vrDisplay_WriteFrames(s.d, dir, 3, VR_FRAMES_PNG, err, sizeof err) == 0, "%s", err);
    ENSURE(check_png(s.d, dir, 0, 64, 40) == 0);
    ENSURE(check_png(s.d, dir, 1, 64, 40) == 0);
    snprintf(ppm, sizeof ppm, "%s/frame-000003-left.ppm", dir);
    ENSURE(stat(ppm, &sb) != 0);      /* PNG instead of PPM, not beside it */
    done(&s);
    ENSURE(remove_tree(dir) == 0);
    return 0;
}

/* a busy scene: a real wireframe table, spheres overlapping it and each other */
static Scene busy_scene(int width, int height)
{
    Scene s = scene(width, height);
    double h[3] = {2, 1, 0.05}, c[3] = {0, 0, -0.5}, p[3];
    char name[16];
    int i;
    add_box(s.w, "table", c, h, 120, 80, 40, 1);
    for (i = 0; i < 12; i++) {
        p[0] = -1.5 + 0.27 * i, p[1] = 0.3 * (i % 3), p[2] = 0.2 * (i % 4);
        snprintf(name, sizeof name, "b%d", i);
        add_sphere(s.w, name, p, 0.1 + 0.03 * i, 20 * i, 255 - 20 * i, 100);
    }
    s.v.see_through = 1;
    return s;
}

static int same_pixels(const vrDisplay *a, const vrDisplay *b)
{
    int e, w, h;
    for (e = 0; e < 2; e++) {
        const unsigned char *pa = vrDisplay_Pixels(a, e, &w, &h), *pb = vrDisplay_Pixels(b, e, NULL, NULL);
        if (!pa || !pb || memcmp(pa, pb, (size_t)w * h * 3) != 0) return 0;
    }
    return 1;
}

static int test_rendering_is_deterministic(void)
{
    Scene s = busy_scene(200, 120), again;
    size_t n = 200 * 120 * 3;
    unsigned char *first = malloc(2 * n);
    int e;
    ENSURE(first && show(&s) == 0);
    for (e = 0; e < 2; e++) memcpy(first + e * n, vrDisplay_Pixels(s.d, e, NULL, NULL), n);
    /* the two eyes differ (the test would pass on a blank image) */
    ENSURE(memcmp(first, first + n, n) != 0);
    again = s;
    again.d = NULL;         /* a second context, drawing the same */
    ENSURE(show(&s) == 0 && show(&again) == 0);
    ENSURE(same_pixels(s.d, again.d));
    for (e = 0; e < 2; e++) ENSURE(memcmp(first + e * n, vrDisplay_Pixels(s.d, e, NULL, NULL), n) == 0);
    /* the contexts take turns: each draws its own view, not the other's */
    again.v.see_through = 2;
    ENSURE(show(&again) == 0 && !same_pixels(s.d, again.d));
    s.v.see_through = 2;
    ENSURE(show(&s) == 0 && same_pixels(s.d, again.d));
    free(first);
    vrDisplay_Close(again.d);
    done(&s);
    return 0;
}

/* ---- errors -------------------------------------------------------------- */
static int test_unwritable_frames_folder_is_a_clear_error(void)
{
    Scene s = busy_scene(32, 32);
    char dir[64], file[128], sub[192];
    long size;
    unsigned char *kept;
    FILE *f;
    ENSURE(make_tmpdir(dir, sizeof dir) == 0);
    snprintf(file, sizeof file, "%s/plain-file", dir);
    f = fopen(file, "w");
    ENSURE(f && fputs("keep me\n", f) >= 0 && fclose(f) == 0);
    ENSURE(show(&s) == 0);
    /* a folder below a plain file, and the plain file as the folder */
    snprintf(sub, sizeof sub, "%s/frames", file);
    ENSURE(vrDisplay_WriteFrames(s.d, sub, 0, VR_FRAMES_PPM, err, sizeof err) == -1);
    ENSURE_MSG(strstr(err, "frames folder") && strstr(err, "plain-file"), "%s", err);
    ENSURE(vrDisplay_WriteFrames(s.d, file, 0, VR_FRAMES_PPM, err, sizeof err) == -1);
    ENSURE_MSG(strstr(err, "plain-file"), "%s", err);
    kept = read_file(file, &size);
    ENSURE(kept && size == 8 && memcmp(kept, "keep me\n", 8) == 0);   /* untouched */
    free(kept);
    done(&s);
    ENSURE(remove_tree(dir) == 0);
    return 0;
}

static int test_bad_resolution_is_an_error_and_the_display_survives(void)
{
    static const int bad[][2] = {{0, 512}, {640, 0}, {15, 512}, {8193, 16}, {100000, 100000}, {-640, 512}};
    Scene s = busy_scene(64, 64);
    vrView good = s.v;
    size_t i;
    int width, height;
    ENSURE(show(&s) == 0);
    for (i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        s.v.width = bad[i][0], s.v.height = bad[i][1];
        ENSURE(vrDisplay_Render(s.d, s.w, &s.v, err, sizeof err) == -1);
        ENSURE_MSG(strstr(err, "resolution") && strstr(err, "16..8192"), "%s", err);
    }
    s.v = good, s.v.fov = 5;
    ENSURE(vrDisplay_Render(s.d, s.w, &s.v, err, sizeof err) == -1 && strstr(err, "fov"));
    s.v = good;
    ENSURE(show(&s) == 0);
    ENSURE(vrDisplay_Pixels(s.d, 1, &width, &height) && width == 64 && height == 64);
    done(&s);
    return 0;
}

static int test_render_time_reaches_stats(void)
{
    Scene s = busy_scene(64, 64);
    vrStats st;
    ENSURE(show(&s) == 0);
    vrWorld_GetStats(s.w, &st);
    ENSURE_MSG(st.render_ms > 0 && st.render_ms < 10000, "render_ms %g", st.render_ms);
    ENSURE(vrDisplay_RendererName(s.d)[0] != '\0');
    done(&s);
    return 0;
}

static const vrTest tests[] = {
    /* first: they need a process in which no display was opened yet */
    TEST(test_world_without_display_does_not_load_osmesa),
    TEST(test_missing_render_module_is_a_clear_error),
    TEST(test_near_point_on_axis_has_crossed_disparity_of_predicted_size),
    TEST(test_far_point_on_axis_has_uncrossed_disparity),
    TEST(test_point_at_focal_distance_has_zero_disparity),
    TEST(test_focal_setting_moves_the_zero_disparity_plane),
    TEST(test_image_is_upright_and_not_mirrored),
    TEST(test_face_toward_the_eye_shows_its_color),
    TEST(test_tilted_face_is_lit_by_ambient_plus_diffuse_cosine),
    TEST(test_sphere_is_smooth_shaded),
    TEST(test_near_object_hides_far_one_in_either_order),
    TEST(test_see_through_draws_real_objects_wire_hidden_or_solid),
    TEST(test_real_object_hides_virtual_object_behind_it),
    TEST(test_frames_are_well_formed_ppm_in_a_created_folder),
    TEST(test_png_frames_decode_to_the_rendered_pixels),
    TEST(test_rendering_is_deterministic),
    TEST(test_unwritable_frames_folder_is_a_clear_error),
    TEST(test_bad_resolution_is_an_error_and_the_display_survives),
    TEST(test_render_time_reaches_stats),
};

const vrTestSuite vrSuite_Render = {"render", tests, TEST_COUNT(tests), NULL, NULL, 0};
