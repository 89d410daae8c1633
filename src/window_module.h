/* window_module.h — the interface between the library (window.c) and the
 * window module vroc-window.so (window_glfw.c), the only code that touches
 * GLFW, GL and X.  Like render.h: one data symbol, a struct of functions.
 * The module shows RGB pixels the render module made, so the window shows
 * exactly the frames' pixels (SPEC 9: the same drawing code as the frames). */
#ifndef VROC_WINDOW_MODULE_H
#define VROC_WINDOW_MODULE_H

#include <stddef.h>
#include "vroc.h"

#define VR_WINDOW_SYMBOL "vroc_window_api"
#define VR_WINDOW_ABI 2            /* 2: resizable (size, and show's fit) */
#define VR_WINDOW_QUEUE 256         /* events kept between two polls */

typedef struct vrWindowContext vrWindowContext;

typedef struct vrWindowApi {
    int abi;
    /* an X window of width x height pixels, not yet shown; NULL and a message */
    vrWindowContext *(*open)(int width, int height, const char *title, char *err, size_t errlen);
    void (*close)(vrWindowContext *c);
    /* puts rgb (rows top to bottom) into the window: resized to fit it
     * until the user resized it, then at its top left, the rest black */
    int (*show)(vrWindowContext *c, const unsigned char *rgb, int width, int height,
                char *err, size_t errlen);
    /* the events queued since the last poll (the oldest dropped past the queue) */
    int (*poll)(vrWindowContext *c, vrWindowEvent *ev, int max);
    /* the framebuffer's size; 1 when the user (not show) gave it */
    int (*size)(const vrWindowContext *c, int *width, int *height);
} vrWindowApi;

#endif
