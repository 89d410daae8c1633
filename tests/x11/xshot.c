/* xshot.c — the window tests' screenshot: `xshot WINDOW-ID OUT.ppm` writes
 * the window's pixels, as the X server holds them, as a binary PPM.  It
 * reads the screen from outside the program under test, so a test of what
 * the window shows does not trust the window's own code. */
#include <X11/Xlib.h>
#include <X11/Xutil.h>
#include <stdio.h>
#include <stdlib.h>

static int channel(unsigned long pixel, unsigned long mask)
{
    int shift = 0;
    if (!mask) return 0;
    while (!(mask & 1)) mask >>= 1, shift++;
    return (int)(((pixel >> shift) & mask) * 255 / mask);
}

int main(int argc, char **argv)
{
    Display *dpy;
    XWindowAttributes wa;
    XImage *img;
    FILE *f;
    int x, y;
    if (argc != 3) {
        fprintf(stderr, "usage: xshot WINDOW-ID OUT.ppm\n");
        return 2;
    }
    dpy = XOpenDisplay(NULL);
    if (!dpy) {
        fprintf(stderr, "xshot: cannot open the X display\n");
        return 1;
    }
    if (!XGetWindowAttributes(dpy, (Window)strtoul(argv[1], NULL, 0), &wa)) return 1;
    img = XGetImage(dpy, (Window)strtoul(argv[1], NULL, 0), 0, 0, (unsigned)wa.width, (unsigned)wa.height,
                    AllPlanes, ZPixmap);
    f = fopen(argv[2], "wb");
    if (!img || !f) {
        fprintf(stderr, "xshot: cannot read the window or write %s\n", argv[2]);
        return 1;
    }
    fprintf(f, "P6\n%d %d\n255\n", wa.width, wa.height);
    for (y = 0; y < wa.height; y++)
        for (x = 0; x < wa.width; x++) {
            unsigned long p = XGetPixel(img, x, y);
            fputc(channel(p, img->red_mask), f);
            fputc(channel(p, img->green_mask), f);
            fputc(channel(p, img->blue_mask), f);
        }
    XDestroyImage(img);
    XCloseDisplay(dpy);
    return fclose(f) == 0 ? 0 : 1;
}
