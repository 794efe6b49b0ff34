/* png_read: reads a PNG file back with libpng as 8-bit RGB, for the tests of images and plots
 * (a file that libpng cannot decode fails the test). */
#ifndef VCSPH_TEST_PNG_READ_H
#define VCSPH_TEST_PNG_READ_H

#include <png.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

typedef struct {
    uint32_t width, height;
    uint8_t *rgb; /* width x height x 3, rows from the top */
} png_rgb;

/* Returns 0, or -1 when the file is missing or is not a PNG that libpng decodes whole. */
static inline int png_read_rgb(const char *path, png_rgb *out)
{
    png_image image;
    memset(&image, 0, sizeof image);
    image.version = PNG_IMAGE_VERSION;
    memset(out, 0, sizeof *out);
    if (!png_image_begin_read_from_file(&image, path)) return -1;
    image.format = PNG_FORMAT_RGB;
    uint8_t *buf = malloc(PNG_IMAGE_SIZE(image));
    if (!buf || !png_image_finish_read(&image, NULL, buf, 0, NULL)) {
        free(buf);
        png_image_free(&image);
        return -1;
    }
    out->width = image.width;
    out->height = image.height;
    out->rgb = buf;
    return 0;
}

static inline const uint8_t *png_pixel(const png_rgb *img, uint32_t x, uint32_t y)
{
    return img->rgb + 3 * ((size_t)y * img->width + x);
}

static inline void png_rgb_free(png_rgb *img)
{
    free(img->rgb);
    img->rgb = NULL;
}

#endif
