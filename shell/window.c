/* window.c — the `window` command and the live window (SPEC 9).
 *
 *   run_window, run_window_mode   the command and the setting
 *   sh_window_service             the window's input, and the frame shown
 *   sh_wait_input                 a wait for input that keeps it live
 *   window_view                   the view as the window draws it (its size)
 *   on_key, on_press, on_motion   what the mouse and the keys do
 *   hand_clock                    the pointer's moments in simulation time
 *
 * The window has a display of its own (the view with ipd 0 in mono), so
 * the frames written keep the shell's view and size.  A trackball drag and
 * the wheel move the head pose itself (sh->view): the frames written, and
 * a later `eye =`, follow the window.  The window is serviced at every
 * frame drawn, and whenever the shell waits for input (the prompt, a pipe),
 * at least every SERVICE_S seconds.
 *
 * The window opens at the frames' resolution (twice as wide side by
 * side) and follows it until the user resizes it; from then on it is
 * drawn for its own size: the view rendered at that size (each eye at
 * half its width side by side), so nothing is stretched, and the pointer
 * and the trackball measure in its pixels.
 */
#include <poll.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "commands.h"
#include "hand.h"

#define SERVICE_S 0.01          /* the window's input is read this often, at least */
#define EVENTS_MAX 64
#define WIN_MIN 16              /* pixels: the render's least (a window made smaller is clipped) */
#define WIN_MAX 8192

typedef struct ShWindow {
    vrWindow *win;
    vrDisplay *display;
    int dirty;                  /* the frame shown is not the current one */
    int dragging;               /* a trackball drag is going on */
    double last_x, last_y;
    ShHand hand;
    int hand_reported;          /* the world refused a sample of this drag: said once */
} ShWindow;

/* ---- the frame shown ------------------------------------------------------- */
static int clamp_size(int v) { return v < WIN_MIN ? WIN_MIN : v > WIN_MAX ? WIN_MAX : v; }

/* the view the window draws: the tracked head's, when one drives the view,
 * at the size the user gave the window (one eye's: half of it side by side) */
static vrView window_view(const Shell *sh)
{
    vrView v = sh_current_view(sh);
    int width, height;
    if (sh->window_mode == VR_WINDOW_MONO) v.ipd = 0;   /* the head's own view */
    if (vrWindow_Size(sh->window->win, &width, &height)) {
        v.width = clamp_size(sh->window_mode == VR_WINDOW_SIDE ? width / 2 : width);
        v.height = clamp_size(height);
    }
    return v;
}

static int show(Shell *sh, char *err, size_t n)
{
    ShWindow *w = sh->window;
    vrView v = window_view(sh);
    if (vrDisplay_Render(w->display, sh->world, &v, err, n) != 0) return -1;
    w->dirty = 0;
    return vrWindow_Show(w->win, w->display, sh->window_mode, err, n);
}

void sh_window_frame(Shell *sh)
{
    if (!sh->window) return;
    sh->window->dirty = 1;
    sh_window_service(sh);
}

static void report(Shell *sh, const char *err)
{
    sh_error_at(sh, "window", err);
}

/* ---- keys -------------------------------------------------------------------- */
static void toggle_run(Shell *sh)
{
    char err[SH_ERR_MAX];
    if (sh->running) {
        sh->running = 0;
        return;
    }
    if (sh_run_realtime(sh, err, sizeof err) != 0) report(sh, err);
    else snprintf(sh->run_origin, sizeof sh->run_origin, "window");
}

static void step_one(Shell *sh)
{
    char err[SH_ERR_MAX];
    if (vrWorld_Step(sh->world, 1, err, sizeof err) != 0 || sh_display_draw(sh, err, sizeof err) != 0)
        report(sh, err);
}

static void reset_view(Shell *sh)
{
    vrView d = vrView_Default();
    memcpy(sh->view.eye, d.eye, sizeof d.eye);
    memcpy(sh->view.look, d.look, sizeof d.look);
    memcpy(sh->view.up, d.up, sizeof d.up);
}

/* g: select mode is the library's setting (SPEC 8), the one `select = 1`
 * and the panel's select button set, so that the three agree */
static void toggle_select(Shell *sh)
{
    vrSettings s = *vrWorld_Settings(sh->world);
    char err[256];
    s.select = !s.select;
    if (vrWorld_SetSettings(sh->world, &s, err, sizeof err) != 0) report(sh, err);
}

static void on_key(Shell *sh, int key)
{
    switch (key) {
    case ' ': toggle_run(sh); break;
    case '.': case 'n': step_one(sh); break;
    case 't': sh->view.see_through = (sh->view.see_through + 1) % 3; break;
    case 'm': sh->window_mode = (vrWindowMode)((sh->window_mode + 1) % 3); break;
    case 'r': reset_view(sh); break;
    case 'g': toggle_select(sh); break;
    case 27: sh_window_close(sh); return;
    default: return;
    }
    if (sh->window) sh->window->dirty = 1;
}

/* ---- the mouse ---------------------------------------------------------------- */
/* the pointer's ray in the view the window shows; side by side, over
 * either eye's half; forward f: the ray through the centre */
static void pointer_ray(const Shell *sh, double x, double y, double o[3], double d[3], double f[3])
{
    vrView v = window_view(sh);
    double c[3];
    if (sh->window_mode == VR_WINDOW_SIDE && x >= v.width) x -= v.width;
    vrView_PointerRay(&v, x + 0.5, y + 0.5, v.width, v.height, o, d);
    vrView_PointerRay(&v, v.width / 2.0, v.height / 2.0, v.width, v.height, c, f);
}

/* the pointer's moments in simulation time (hand.h): in a real-time run
 * the next frame, due at sh->next_frame, ends at the next frame end, and
 * time runs at one simulated second a second between the frames; else
 * what the pointer does happens in the frame to come, at its end */
static HandClock hand_clock(const Shell *sh)
{
    HandClock c;
    c.now = vrWorld_Time(sh->world);
    c.next = vrWorld_NextFrameEnd(sh->world);
    c.wall_next = sh->next_frame;
    c.rate = sh->running ? 1 : 0;
    return c;
}

/* a hand call's result: a refused sample is said once a drag */
static void hand_result(Shell *sh, int r)
{
    ShWindow *w = sh->window;
    if (r >= 0 || w->hand_reported) return;
    w->hand_reported = 1;
    report(sh, w->hand.error);
}

static void on_press(Shell *sh, const vrWindowEvent *e)
{
    ShWindow *w = sh->window;
    HandClock c = hand_clock(sh);
    double o[3], d[3], f[3];
    int r;
    if (e->button != 1) return;
    pointer_ray(sh, e->x, e->y, o, d, f);
    if (vrWorld_Settings(sh->world)->select) {
        w->hand_reported = 0;
        r = hand_press(&w->hand, sh->world, o, d, f, &c, e->time);
        hand_result(sh, r);
        if (r != 0) return;
    }
    w->dragging = 1;
    w->last_x = e->x, w->last_y = e->y;
}

static void on_motion(Shell *sh, const vrWindowEvent *e)
{
    ShWindow *w = sh->window;
    HandClock c = hand_clock(sh);
    double o[3], d[3], f[3], k;
    if (w->hand.held) {
        pointer_ray(sh, e->x, e->y, o, d, f);
        hand_result(sh, hand_move(&w->hand, sh->world, o, d, &c, e->time));
    } else if (w->dragging) {
        /* half a turn per height of the window as drawn, not of the frames */
        k = (double)sh->view.height / window_view(sh).height;
        vrView_Trackball(&sh->view, k * (e->x - w->last_x), k * (e->y - w->last_y));
        w->last_x = e->x, w->last_y = e->y;
        w->dirty = 1;
    }
}

static void on_release(Shell *sh, const vrWindowEvent *e)
{
    ShWindow *w = sh->window;
    HandClock c = hand_clock(sh);
    double o[3], d[3], f[3];
    if (e->button != 1) return;
    if (w->hand.held) {
        pointer_ray(sh, e->x, e->y, o, d, f);
        hand_result(sh, hand_release(&w->hand, sh->world, o, d, &c, e->time));
    }
    w->dragging = 0;
}

static void on_event(Shell *sh, const vrWindowEvent *e)
{
    switch (e->type) {
    case VR_WEV_PRESS: on_press(sh, e); break;
    case VR_WEV_RELEASE: on_release(sh, e); break;
    case VR_WEV_MOTION: on_motion(sh, e); break;
    case VR_WEV_SCROLL:
        vrView_Zoom(&sh->view, e->amount);
        sh->window->dirty = 1;
        break;
    case VR_WEV_KEY: on_key(sh, e->key); break;
    case VR_WEV_CLOSE: sh_window_close(sh); break;
    case VR_WEV_RESIZE: sh->window->dirty = 1; break;
    }
}

/* ---- servicing ------------------------------------------------------------------ */
void sh_window_service(Shell *sh)
{
    vrWindowEvent ev[EVENTS_MAX];
    char err[SH_ERR_MAX];
    int n, i;
    if (!sh->window) return;
    n = vrWindow_Poll(sh->window->win, ev, EVENTS_MAX);
    for (i = 0; i < n && sh->window; i++) on_event(sh, &ev[i]);
    if (sh->window && sh->window->dirty && show(sh, err, sizeof err) != 0) {
        report(sh, err);
        sh_window_close(sh);
    }
}

double sh_window_wait(const Shell *sh)
{
    return sh->window ? SERVICE_S : -1;
}

void sh_wait_input(Shell *sh, int fd)
{
    struct pollfd p;
    char err[SH_ERR_MAX];
    p.fd = fd, p.events = POLLIN;
    while (sh->window || sh->running) {
        double wait = sh_frame_wait(sh), win = sh_window_wait(sh);
        if (win >= 0 && (wait < 0 || win < wait)) wait = win;
        p.revents = 0;
        if (poll(&p, 1, (int)(wait * 1000)) != 0) return;   /* input, or an error getline will see */
        sh_window_service(sh);
        if (sh_frame_wait(sh) == 0 && sh_tick(sh, err, sizeof err) != 0) sh_error_at(sh, sh->run_origin, err);
        if (sh_interrupted) return;
    }
}

/* ---- the command ------------------------------------------------------------------ */
void sh_window_close(Shell *sh)
{
    if (!sh->window) return;
    vrWindow_Close(sh->window->win);
    vrDisplay_Close(sh->window->display);
    hand_done(&sh->window->hand);
    free(sh->window);
    sh->window = NULL;
}

/* `window`: opens it (once) and shows the current frame, drawn as
 * `refresh` draws it (the frame files too, when they are written) */
int run_window(Shell *sh, const Stmt *st, char *err, size_t n)
{
    ShWindow *w;
    (void)st;
    if (!sh->window) {
        w = calloc(1, sizeof *w);
        if (!w) {
            snprintf(err, n, "out of memory");
            return -1;
        }
        if (vrWindow_Open(&w->win, err, n) != 0 || vrDisplay_Open(&w->display, err, n) != 0) {
            vrWindow_Close(w->win);
            free(w);
            return -1;
        }
        hand_init(&w->hand);
        sh->window = w;
    }
    sh->window->dirty = 1;
    if (sh_display_draw(sh, err, n) != 0) return -1;
    if (sh->window && sh->window->dirty && show(sh, err, n) != 0) {
        sh_window_close(sh);
        return -1;
    }
    return 0;
}

int run_window_mode(Shell *sh, const Stmt *st, char *err, size_t n)
{
    (void)err, (void)n;
    sh->window_mode = (vrWindowMode)st->choice;
    if (sh->window) sh->window->dirty = 1;
    return 0;
}
