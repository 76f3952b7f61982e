/* apng.h - animated PNG output (APNG, the PNG extension every current
 * browser plays; viewers without it show the first frame).
 *
 * Frames are added one at a time, so an animation of a thousand large
 * frames needs memory for two frames only. Each frame after the first is
 * stored as the rectangle where it differs from the one before (blend
 * SOURCE, dispose NONE), which for simulation frames - a still grid and
 * labels, moving particles - is most of the saving. Output is
 * deterministic: the same frames give the same bytes. Written atomically
 * (atomic_file.h). */
#ifndef LAMINA_APNG_H
#define LAMINA_APNG_H

#include <stddef.h>

#include "render.h"

typedef struct lr_apng lr_apng;

/* An animation of nframes (>= 1) frames of w x h straight RGBA8 pixels,
 * shown at fps frames per second (0.02 .. 1000) and played `loops` times
 * (0: for ever). text: tEXt chunks (provenance). NULL with err set on
 * failure. */
lr_apng *lr_apng_open(const char *path, int w, int h, unsigned nframes, double fps,
                      unsigned loops, const lr_text_chunk *text, size_t ntext,
                      char *err, size_t errlen);
/* Adds the next frame (rows top to bottom, stride 4 w). */
int lr_apng_add(lr_apng *a, const unsigned char *rgba, char *err, size_t errlen);
/* Writes the end and renames the file into place; fails if fewer frames
 * were added than announced. Frees a either way. */
int lr_apng_close(lr_apng *a, char *err, size_t errlen);
/* Gives up: removes the temporary, frees a. */
void lr_apng_abort(lr_apng *a);

#endif
