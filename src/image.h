/* image.h — one RGB image into a file: binary PPM (SPEC 4's header, exactly
 * `P6\n<w> <h>\n255\n`) or PNG (libpng, 8-bit RGB), so that a run needs no
 * converter.  Rows top to bottom, width*height*3 bytes.  A file that cannot
 * be written whole is removed: no truncated frame is left behind. */
#ifndef VROC_IMAGE_H
#define VROC_IMAGE_H

#include <stddef.h>

int vrImage_WritePPM(const char *path, const unsigned char *rgb, int width, int height,
                     char *err, size_t errlen);
int vrImage_WritePNG(const char *path, const unsigned char *rgb, int width, int height,
                     char *err, size_t errlen);

#endif
