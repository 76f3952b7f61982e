/* fuzz_png.c - libFuzzer target: the PNG reader (lamina diff, thumbnails,
 * animate) on arbitrary bytes. It must return an image or an error, never
 * crash, and never allocate for dimensions it refuses (issue 18). */
#include <stdint.h>
#include <stdlib.h>

#include "fuzz_file.h"
#include "render.h"
#include "fuzz_target.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    int w = 0, h = 0;
    unsigned char *rgba = NULL;
    char err[512];
    if (lr_png_read(fuzz_file(data, size), &w, &h, &rgba, err, sizeof err) == 0) {
        if (w <= 0 || h <= 0 || !rgba) abort();
        unsigned sum = 0;   /* the pixels can be read (ASan checks the bounds) */
        for (size_t i = 0; i < 4 * (size_t)w * (size_t)h; i += 4099) sum += rgba[i];
        free(rgba);
        if (sum == 1u << 31) abort();   /* uses sum: the loop is not optimised away */
    }
    return 0;
}
