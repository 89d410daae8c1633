/* bench_window.c — frames per second of the live window (SPEC 9).
 *
 * The window's frame is the render module's stereo render, composed for
 * the mode and drawn into the X window (glDrawPixels, swap): the Office
 * scene and 1000 objects (render_scenes.h), at 640x512, in each mode, and
 * Office at 1280x1024 (a window the user made larger is drawn at its size:
 * four times the pixels).
 * When $DISPLAY is unset it runs its own Xvfb (the X server's copy is part
 * of what a frame costs there; a real display's GPU copy is cheaper).
 * Prints a table and CSV lines (`csv,window,...`); asserts nothing.
 */
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "vroc.h"
#define BENCH_NAME "bench_window"
#include "render_scenes.h"

static const char *const mode_names[3] = {"mono", "side", "anaglyph"};

static double now_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec + ts.tv_nsec / 1e9;
}

/* a private X server on the first free display :70.. ; its pid, or -1 */
static pid_t start_xvfb(void)
{
    char name[16], lock[64], sock[64];
    int n, i;
    for (n = 70; n < 90; n++) {
        pid_t pid;
        snprintf(lock, sizeof lock, "/tmp/.X%d-lock", n);
        if (access(lock, F_OK) == 0) continue;
        snprintf(name, sizeof name, ":%d", n);
        pid = fork();
        if (pid == 0) {
            freopen("/dev/null", "w", stderr);
            execlp("Xvfb", "Xvfb", name, "-screen", "0", "1600x1200x24", "-nolisten", "tcp", (char *)NULL);
            _exit(127);
        }
        snprintf(sock, sizeof sock, "/tmp/.X11-unix/X%d", n);
        for (i = 0; i < 100 && access(sock, F_OK) != 0; i++) {
            struct timespec ts = {0, 50000000};
            nanosleep(&ts, NULL);
        }
        if (access(sock, F_OK) == 0) {
            setenv("DISPLAY", name, 1);
            return pid;
        }
        kill(pid, SIGTERM);
        waitpid(pid, NULL, 0);
    }
    return -1;
}

/* window frames per second over `frames` renders and shows */
static double rate(vrDisplay *d, vrWindow *win, vrWorld *w, const vrView *v, vrWindowMode mode, int frames)
{
    vrWindowEvent ev[64];
    double t0 = now_s();
    int i;
    for (i = 0; i < frames; i++) {
        if (vrDisplay_Render(d, w, v, err, sizeof err) || vrWindow_Show(win, d, mode, err, sizeof err)) {
            fprintf(stderr, "bench_window: %s\n", err);
            return 0;
        }
        vrWindow_Poll(win, ev, 64);
    }
    return frames / (now_s() - t0);
}

static const char *size_name(int width, int height)
{
    static char b[32];
    snprintf(b, sizeof b, "%dx%d", width, height);
    return b;
}

static void run(vrDisplay *d, vrWindow *win, const char *scene, vrWorld *w, int frames, int width, int height)
{
    vrView v = vrView_Default();
    double fps[3];
    int m;
    v.width = width, v.height = height;
    v.eye[1] = -6, v.eye[2] = 3;        /* the whole scene in view, as bench_render */
    v.look[2] = 0.8;
    for (m = 0; m < 3; m++) {
        rate(d, win, w, &v, (vrWindowMode)m, 3);   /* warm-up, and the window's new size */
        fps[m] = rate(d, win, w, &v, (vrWindowMode)m, frames);
        printf("csv,window,%s,%d,%s,%dx%d,%.2f\n", scene, vrWorld_ObjectCount(w), mode_names[m], v.width,
               v.height, fps[m]);
    }
    printf("%-8s %8d %10s %10.1f %10.1f %10.1f\n", scene, vrWorld_ObjectCount(w), size_name(width, height), fps[0],
           fps[1], fps[2]);
}

int main(void)
{
    pid_t xvfb = -1;
    vrDisplay *d = NULL;
    vrWindow *win = NULL;
    vrWorld *w;
    const char *x = getenv("DISPLAY");
    if ((!x || !x[0]) && (xvfb = start_xvfb()) < 0) {
        fprintf(stderr, "bench_window: no $DISPLAY and cannot start Xvfb\n");
        return 1;
    }
    if (vrDisplay_Open(&d, err, sizeof err) || vrWindow_Open(&win, err, sizeof err)) {
        fprintf(stderr, "bench_window: %s\n", err);
        return 1;
    }
    printf("window frames/s on %s (%s): render both eyes + compose + show\n",
           getenv("DISPLAY"), xvfb > 0 ? "its own Xvfb" : "the user's display");
    printf("%-8s %8s %10s %10s %10s %10s\n", "scene", "objects", "eye", "mono", "side", "anaglyph");
    w = office();
    run(d, win, "office", w, 100, 640, 512);
    run(d, win, "office", w, 25, 1280, 1024);
    vrWorld_Destroy(w);
    w = crowd();
    run(d, win, "crowd", w, 10, 640, 512);
    vrWorld_Destroy(w);
    vrWindow_Close(win);
    vrDisplay_Close(d);
    if (xvfb > 0) {
        kill(xvfb, SIGTERM);
        waitpid(xvfb, NULL, 0);
    }
    return 0;
}
