/* diff.h - are two images the same picture? (`lamina diff`, the visual
 * regression tests and the gallery's baselines all ask through here.)
 *
 * Identical bytes are the fast path. Otherwise every pixel gets a perceptual
 * distance (YIQ, Kotsarenko & Ramos 2010), and a pixel above the threshold
 * is checked for anti-aliasing: a pixel on the edge of a flat shape in
 * either image, with a darker and a brighter neighbour, is taken to be the
 * same edge rendered a fraction of a pixel elsewhere, not a difference.
 *
 * The verdict "same" needs all of:
 *   - no pixel over the hard limit (largest channel difference) that is not
 *     anti-aliasing: one moved particle is a change however small;
 *   - at most max_pixels differing pixels overall;
 *   - at most max_window of them in any 16 x 16 window: a few scattered
 *     pixels are noise, the same number in one spot is a shape.
 *
 * Pure functions on RGBA8 buffers; lr_diff_files adds the PNG reading.
 * Errors are values: 0 success, -1 with a message in err[errlen]. */
#ifndef LAMINA_DIFF_H
#define LAMINA_DIFF_H

#include <stddef.h>

#define LR_DIFF_WINDOW 16   /* side of the window the worst count is taken over */

typedef struct lr_diff_opts {
    double threshold;   /* perceptual distance 0..1 below which a pixel is unchanged */
    int hard_limit;     /* largest channel difference (0..255) a non-AA pixel may have */
    long max_pixels;    /* differing pixels allowed overall */
    long max_window;    /* differing pixels allowed in any 16 x 16 window */
} lr_diff_opts;

/* threshold 0.1, hard limit 64, 16 pixels overall, 8 in a window */
void lr_diff_defaults(lr_diff_opts *o);

typedef struct lr_diff_result {
    int width, height;
    int exact;          /* identical RGBA bytes (the fast path was taken) */
    int same;           /* the verdict: same within tolerance */
    long differing;     /* pixels above the threshold and not anti-aliasing */
    long aa;            /* pixels above the threshold judged anti-aliasing */
    long hard;          /* differing pixels over the hard limit */
    long window_max;    /* most differing pixels in one 16 x 16 window */
    int window_x, window_y;     /* that window's top-left pixel */
    int max_channel;    /* largest channel difference of any pixel */
    int max_channel_differing;  /* ... of any differing (non-AA) pixel */
} lr_diff_result;

/* Compares two w x h straight-alpha RGBA8 images. When diff_rgba is not
 * NULL (w*h*4 bytes) it receives the diff image: differing pixels red,
 * anti-aliasing yellow, the rest the expected image in faded grey. */
int lr_diff(const unsigned char *expected, const unsigned char *actual, int w, int h,
            const lr_diff_opts *opts, lr_diff_result *res, unsigned char *diff_rgba,
            char *err, size_t errlen);

/* Reads both PNGs and compares them; writes the diff image to diff_path
 * unless it is NULL. Unreadable or corrupt files and a size mismatch
 * ("size mismatch: 64x64 vs 64x32") are errors. */
int lr_diff_files(const char *expected, const char *actual, const lr_diff_opts *opts,
                  const char *diff_path, lr_diff_result *res, char *err, size_t errlen);

/* One line (no newline) describing the result, e.g.
 * "different: 57 differing pixels (41 in the worst 16x16 window at 120,88), ..." */
void lr_diff_summary(const lr_diff_result *res, const lr_diff_opts *opts,
                     char *buf, size_t len);

#endif
