/* window.c — the library side of the live window (SPEC 9).
 *
 *   vrWindow_Open    checks $DISPLAY, loads vroc-window.so (module.h)
 *   vrWindow_Show    composes a display's two eyes for the mode (compose)
 *   vrWindow_Size    its size, and whether the user chose it
 *   vrWindow_Poll    the window's input events
 *
 * Nothing here references GLFW or X: a run that never opens a window never
 * loads them.
 */
#include <stdlib.h>
#include <string.h>

#include "vroc.h"
#include "module.h"
#include "render.h"
#include "window_module.h"

#define MODULE_FILE "vroc-window.so"

struct vrWindow {
    const vrWindowApi *api;
    vrWindowContext *ctx;
    unsigned char *rgb;        /* the composed image */
    size_t cap;
};

static const vrWindowApi *module_api;

static int load_module(char *err, size_t errlen)
{
    const vrWindowApi *api;
    if (module_api) return 0;
    api = vrModule_Load("window module", MODULE_FILE, "VROC_WINDOW_MODULE", VR_WINDOW_SYMBOL, err, errlen);
    if (api && api->abi != VR_WINDOW_ABI) {
        vrRender_Error(err, errlen, "the window module " MODULE_FILE " is another interface version; rebuild it");
        api = NULL;
    }
    module_api = api;
    return api ? 0 : -1;
}

int vrWindow_Open(vrWindow **out, char *err, size_t errlen)
{
    const char *x = getenv("DISPLAY");
    vrWindow *win;
    *out = NULL;
    if (!x || !x[0]) {
        vrRender_Error(err, errlen, "window: $DISPLAY is not set: there is no X server to open a window "
                "on (log in graphically, ssh -X, or run under xvfb-run); frames = DIR still writes the frames");
        return -1;
    }
    if (load_module(err, errlen)) return -1;
    win = calloc(1, sizeof *win);
    if (!win) {
        vrRender_Error(err, errlen, "out of memory");
        return -1;
    }
    win->api = module_api;
    win->ctx = win->api->open(640, 512, "vroc", err, errlen);
    if (!win->ctx) {
        free(win);
        return -1;
    }
    *out = win;
    return 0;
}

void vrWindow_Close(vrWindow *win)
{
    if (!win) return;
    win->api->close(win->ctx);
    free(win->rgb);
    free(win);
}

/* side: left | right; anaglyph: red of the left eye, green and blue of the
 * right (red-cyan glasses, red over the left eye) */
static void compose(const unsigned char *l, const unsigned char *r, int w, int h, vrWindowMode mode,
                    unsigned char *out)
{
    size_t row = (size_t)w * 3, y, i;
    for (y = 0; y < (size_t)h; y++) {
        const unsigned char *lr = l + y * row, *rr = r + y * row;
        if (mode == VR_WINDOW_SIDE) {
            memcpy(out + y * 2 * row, lr, row);
            memcpy(out + y * 2 * row + row, rr, row);
            continue;
        }
        for (i = 0; i < row; i += 3) {
            unsigned char *o = out + y * row + i;
            o[0] = lr[i];
            o[1] = mode == VR_WINDOW_ANAGLYPH ? rr[i + 1] : lr[i + 1];
            o[2] = mode == VR_WINDOW_ANAGLYPH ? rr[i + 2] : lr[i + 2];
        }
    }
}

int vrWindow_Show(vrWindow *win, const vrDisplay *d, vrWindowMode mode, char *err, size_t errlen)
{
    int w, h, ww;
    const unsigned char *l = vrDisplay_Pixels(d, 0, &w, &h), *r = vrDisplay_Pixels(d, 1, NULL, NULL);
    size_t need;
    if (!l || !r) {
        vrRender_Error(err, errlen, "window: no frame rendered yet");
        return -1;
    }
    ww = mode == VR_WINDOW_SIDE ? 2 * w : w;
    need = (size_t)ww * (size_t)h * 3;
    if (need > win->cap) {
        unsigned char *p = realloc(win->rgb, need);
        if (!p) {
            vrRender_Error(err, errlen, "out of memory for a %dx%d window", ww, h);
            return -1;
        }
        win->rgb = p, win->cap = need;
    }
    compose(l, r, w, h, mode, win->rgb);
    return win->api->show(win->ctx, win->rgb, ww, h, err, errlen);
}

int vrWindow_Size(const vrWindow *win, int *width, int *height)
{
    return win->api->size(win->ctx, width, height);
}

int vrWindow_Poll(vrWindow *win, vrWindowEvent *ev, int max)
{
    return win ? win->api->poll(win->ctx, ev, max) : 0;
}
