/* window_glfw.c — the window module (vroc-window.so): GLFW and OpenGL.
 *
 * One GLFW window with a GL context; show() draws the pixels it is given
 * with glDrawPixels, so the window shows bit for bit what the render module
 * drew for the frame files.  GLFW's callbacks queue the input as
 * vrWindowEvents, each stamped with the monotonic clock: the shell reads
 * them with poll() whenever it waits (SPEC 9).  Vsync is off: showing a
 * frame never waits for the screen.
 *
 * Built alone (this file + window_module.h) with -lglfw -lGL and
 * dlopen()ed by window.c.
 */
#define GL_GLEXT_PROTOTYPES 1
#define GLFW_INCLUDE_GLEXT
#include <GLFW/glfw3.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "window_module.h"
#include "render.h"

struct vrWindowContext {
    GLFWwindow *win;
    int width, height;                 /* the pixels last shown */
    int fb_width, fb_height;           /* the window's, as the X server last told */
    int asked_width, asked_height;     /* the size show() set: not the user's */
    int user_sized;                    /* the user (or a window manager) gave another */
    const unsigned char *rgb;          /* they: the caller keeps them until the next show */
    vrWindowEvent queue[VR_WINDOW_QUEUE];
    int head, count;                   /* a ring: count events from head */
};

static void on_refresh(GLFWwindow *w);

static char glfw_message[256];         /* the last GLFW error, for our messages */

static void on_glfw_error(int code, const char *what)
{
    (void)code;
    snprintf(glfw_message, sizeof glfw_message, "%s", what ? what : "unknown error");
}

static double now_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + (double)ts.tv_nsec * 1e-9;
}

/* ---- input --------------------------------------------------------------- */
static vrWindowEvent *push(GLFWwindow *w, vrWindowEventType type, int button, int key, double amount)
{
    vrWindowContext *c = glfwGetWindowUserPointer(w);
    vrWindowEvent *e;
    if (c->count == VR_WINDOW_QUEUE) {     /* full: the oldest goes */
        c->head = (c->head + 1) % VR_WINDOW_QUEUE;
        c->count--;
    }
    e = &c->queue[(c->head + c->count++) % VR_WINDOW_QUEUE];
    memset(e, 0, sizeof *e);
    e->type = type, e->button = button, e->key = key, e->amount = amount;
    glfwGetCursorPos(w, &e->x, &e->y);
    e->time = now_s();
    return e;
}

static void on_button(GLFWwindow *w, int button, int action, int mods)
{
    static const int ours[3] = {1, 3, 2};   /* GLFW: left, right, middle */
    (void)mods;
    if (button < 0 || button > 2) return;
    push(w, action == GLFW_PRESS ? VR_WEV_PRESS : VR_WEV_RELEASE, ours[button], 0, 0);
}

static void on_motion(GLFWwindow *w, double x, double y)
{
    (void)x, (void)y;
    push(w, VR_WEV_MOTION, 0, 0, 0);
}

static void on_scroll(GLFWwindow *w, double dx, double dy)
{
    (void)dx;
    push(w, VR_WEV_SCROLL, 0, 0, dy);
}

/* keys as ASCII: letters lower case, digits, space, '.', Esc 27 */
static int ascii_key(int key)
{
    if (key >= GLFW_KEY_A && key <= GLFW_KEY_Z) return key - GLFW_KEY_A + 'a';
    if ((key >= GLFW_KEY_0 && key <= GLFW_KEY_9) || key == GLFW_KEY_SPACE || key == GLFW_KEY_PERIOD) return key;
    if (key == GLFW_KEY_ESCAPE) return 27;
    return 0;
}

static void on_key(GLFWwindow *w, int key, int scancode, int action, int mods)
{
    int k = ascii_key(key);
    (void)scancode, (void)mods;
    if (action == GLFW_PRESS && k) push(w, VR_WEV_KEY, 0, k, 0);
}

/* a size that is not the one show() asked for is the user's (or a window
 * manager's that refused ours): from then on the window keeps it and the
 * shell draws for it.  On X11 the framebuffer's pixels are the pointer's
 * coordinates, so the shell measures both alike. */
static void on_framebuffer(GLFWwindow *w, int width, int height)
{
    vrWindowContext *c = glfwGetWindowUserPointer(w);
    vrWindowEvent *e;
    c->fb_width = width, c->fb_height = height;
    if (width != c->asked_width || height != c->asked_height) c->user_sized = 1;
    e = push(w, VR_WEV_RESIZE, 0, 0, 0);
    e->width = width, e->height = height;
}

static void on_close(GLFWwindow *w)
{
    glfwSetWindowShouldClose(w, GLFW_FALSE);   /* the shell decides */
    push(w, VR_WEV_CLOSE, 0, 0, 0);
}

/* ---- the window ------------------------------------------------------------ */
static vrWindowContext *open_window(int width, int height, const char *title, char *err, size_t errlen)
{
    vrWindowContext *c = calloc(1, sizeof *c);
    glfwSetErrorCallback(on_glfw_error);
    if (!c || !glfwInit()) {
        vrRender_Error(err, errlen, "window: %s", c ? glfw_message : "out of memory");
        free(c);
        return NULL;
    }
    glfwWindowHint(GLFW_RESIZABLE, GLFW_TRUE);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 2);
    c->win = glfwCreateWindow(width, height, title, NULL, NULL);
    if (!c->win) {
        vrRender_Error(err, errlen, "window: %s", glfw_message);
        free(c);
        return NULL;
    }
    glfwSetWindowUserPointer(c->win, c);
    glfwSetMouseButtonCallback(c->win, on_button);
    glfwSetCursorPosCallback(c->win, on_motion);
    glfwSetScrollCallback(c->win, on_scroll);
    glfwSetKeyCallback(c->win, on_key);
    glfwSetWindowCloseCallback(c->win, on_close);
    glfwSetWindowRefreshCallback(c->win, on_refresh);
    glfwSetFramebufferSizeCallback(c->win, on_framebuffer);
    glfwMakeContextCurrent(c->win);
    glfwSwapInterval(0);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    c->width = width, c->height = height;
    c->asked_width = width, c->asked_height = height;
    glfwGetFramebufferSize(c->win, &c->fb_width, &c->fb_height);
    return c;
}

/* GLFW stays initialised until the process ends, as the modules stay
 * loaded (module.h): glfwTerminate dlclose()s the X libraries GLFW opened,
 * and the memory they keep would then be lost, not just held */
static void close_window(vrWindowContext *c)
{
    if (!c) return;
    glfwDestroyWindow(c->win);
    free(c);
}

/* a new size: the X server resizes the window asynchronously, and pixels
 * drawn before it has are clipped to the old size */
static void resize(vrWindowContext *c, int width, int height)
{
    int w = 0, h = 0, i;
    c->asked_width = width, c->asked_height = height;
    glfwSetWindowSize(c->win, width, height);
    for (i = 0; i < 100; i++) {
        glfwGetFramebufferSize(c->win, &w, &h);
        if (w == width && h == height) break;
        glfwWaitEventsTimeout(0.01);
    }
    c->fb_width = w, c->fb_height = h;
}

/* the pixels at the top left, black where they do not reach (a window the
 * user made larger than them, until the shell draws for its size) */
static void draw(vrWindowContext *c)
{
    glViewport(0, 0, c->fb_width, c->fb_height);
    glClearColor(0, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    /* rows top to bottom: start at the top left corner, draw downwards */
    glWindowPos2i(0, c->fb_height);
    glPixelZoom(1, -1);
    glDrawPixels(c->width, c->height, GL_RGB, GL_UNSIGNED_BYTE, c->rgb);
    glfwSwapBuffers(c->win);
}

/* an expose (the window uncovered or mapped): the last pixels again */
static void on_refresh(GLFWwindow *w)
{
    vrWindowContext *c = glfwGetWindowUserPointer(w);
    if (!c->rgb) return;
    glfwMakeContextCurrent(NULL);
    glfwMakeContextCurrent(w);
    draw(c);
}

static int show(vrWindowContext *c, const unsigned char *rgb, int width, int height,
                char *err, size_t errlen)
{
    /* OSMesa and GLX share Mesa's dispatch (libglapi): after the render
     * module drew, GLX must really bind again, not trust that it still is */
    glfwMakeContextCurrent(NULL);
    glfwMakeContextCurrent(c->win);
    if (!c->user_sized && (width != c->fb_width || height != c->fb_height)) resize(c, width, height);
    c->width = width, c->height = height;
    c->rgb = rgb;
    draw(c);
    if (glGetError() != GL_NO_ERROR) {
        vrRender_Error(err, errlen, "window: OpenGL error while showing a frame");
        return -1;
    }
    return 0;
}

static int poll_events(vrWindowContext *c, vrWindowEvent *ev, int max)
{
    int n = 0;
    glfwPollEvents();
    while (c->count && n < max) {
        ev[n++] = c->queue[c->head];
        c->head = (c->head + 1) % VR_WINDOW_QUEUE;
        c->count--;
    }
    return n;
}

static int size(const vrWindowContext *c, int *width, int *height)
{
    *width = c->fb_width, *height = c->fb_height;
    return c->user_sized;
}

/* the module's one export (window_module.h) */
const vrWindowApi vroc_window_api = {VR_WINDOW_ABI, open_window, close_window, show, poll_events, size};
