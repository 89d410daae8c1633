/* image.c — frame files: PPM and PNG (image.h).
 *
 *   vrImage_WritePPM   header and all pixels with one fwrite each
 *                      (DEPENDENCIES.md: per pixel halves the frame rate)
 *   vrImage_WritePNG   libpng's simplified API (1.6): no setjmp here, the
 *                      library reports through png_image.message
 */
#include <errno.h>
#include <png.h>
#include <stdio.h>
#include <string.h>

#include "image.h"
#include "render.h"

int vrImage_WritePPM(const char *path, const unsigned char *rgb, int width, int height,
                     char *err, size_t errlen)
{
    FILE *f = fopen(path, "wb");
    size_t bytes = (size_t)width * (size_t)height * 3;
    int ok;
    if (!f) {
        vrRender_Error(err, errlen, "cannot write '%s': %s", path, strerror(errno));
        return -1;
    }
    errno = 0;
    ok = fprintf(f, "P6\n%d %d\n255\n", width, height) > 0;
    ok = ok && fwrite(rgb, 1, bytes, f) == bytes;
    ok = fclose(f) == 0 && ok;
    if (!ok) {
        vrRender_Error(err, errlen, "cannot write '%s': %s", path, strerror(errno ? errno : EIO));
        remove(path);
        return -1;
    }
    return 0;
}

int vrImage_WritePNG(const char *path, const unsigned char *rgb, int width, int height,
                     char *err, size_t errlen)
{
    png_image img;
    memset(&img, 0, sizeof img);
    img.version = PNG_IMAGE_VERSION;
    img.width = (png_uint_32)width;
    img.height = (png_uint_32)height;
    img.format = PNG_FORMAT_RGB;
    errno = 0;
    if (!png_image_write_to_file(&img, path, 0, rgb, 0, NULL)) {
        vrRender_Error(err, errlen, "cannot write '%s': %s", path,
                errno ? strerror(errno) : img.message);
        png_image_free(&img);
        remove(path);
        return -1;
    }
    return 0;
}
