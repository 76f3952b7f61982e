/* plot.h - time-series plots: axes, ticks, grid, legend, several series,
 * drawn with cairo to PNG, the data optionally also written as CSV.
 *
 * Like the rest of src/render, nothing here knows about Lua or the engine: a
 * plot is plain arrays (lr_plot), so it can be tested alone and driven from
 * any binding. Errors are values: 0 on success, -1 with a one-line message in
 * err[errlen]. */
#ifndef LAMINA_PLOT_H
#define LAMINA_PLOT_H

#include <stddef.h>

#include "render.h"

typedef struct lr_plot_series {
    size_t n;                   /* points; 0 is an error naming the series */
    const double *x, *y;        /* n each; a NaN or infinite point is left
                                   out and breaks the line there */
    const char *label;          /* legend text; NULL or "": not in the legend */
    int colour;                 /* lr_palette index (0 = blue, 1 = vermilion…) */
    int dashed;                 /* dashed line (reference curves) */
    int markers;                /* markers only, no line */
    double width;               /* line width in pixels; <= 0: 1.5 */
} lr_plot_series;

/* Where the legend box sits inside the plot area. Zero is the default. */
typedef enum lr_legend {
    LR_LEGEND_TOP_RIGHT = 0,
    LR_LEGEND_TOP_LEFT,
    LR_LEGEND_TOP,
    LR_LEGEND_BOTTOM_RIGHT,
    LR_LEGEND_BOTTOM_LEFT,
    LR_LEGEND_BOTTOM,
    LR_LEGEND_LEFT,
    LR_LEGEND_RIGHT,
    LR_LEGEND_CENTER,
    LR_LEGEND_BEST,             /* the first of the nine places above (in the
                                   order top right, top left, bottom right,
                                   bottom left, right, left, top, bottom,
                                   center) that hides the fewest data */
    LR_LEGEND_NONE
} lr_legend;

typedef struct lr_plot {
    int width, height;          /* pixels */
    const char *title;          /* each may be NULL */
    const char *xlabel, *ylabel;
    int fixed_x, fixed_y;       /* 1: use [x0, x1] / [y0, y1] as given */
    double x0, x1, y0, y1;      /* else: the data's range, padded a little */
    lr_legend legend;
    size_t nseries;
    const lr_plot_series *series;
    const char *csv;            /* NULL, or where to write the data as CSV */
} lr_plot;

/* Draws the plot and writes it to `path` as PNG (atomically, lr_png_write),
 * with `text` as tEXt chunks (provenance); then, if p->csv is set, the data
 * as CSV (lr_plot_write_csv). Nothing is written when the plot is invalid. */
int lr_plot_write(const lr_plot *p, const char *path, const lr_text_chunk *text,
                  size_t ntext, char *err, size_t errlen);

/* The data as CSV: one (x, y) column pair per series, headed "<label> x",
 * "<label> y" ("series <k>" when unlabelled); shorter series leave their
 * cells empty. Numbers round-trip (%.17g); non-finite values are written as
 * nan, inf, -inf. Atomic: a temporary file in the same folder, then rename;
 * missing folders are created; an existing target that is not a regular
 * file is refused. */
int lr_plot_write_csv(const lr_plot *p, const char *path, char *err, size_t errlen);

/* ---- ticks (exposed for tests) ------------------------------------------ */

#define LR_TICK_LABEL_MAX 32

/* "Nice" ticks for the axis range [lo, hi]: the smallest step of the form
 * 1, 2 or 5 x 10^k that divides the range into at most max_intervals parts,
 * and every multiple of it inside [lo, hi] (with a relative slack of 1e-9,
 * so an end that is a multiple is kept). Writes at most cap ticks, in
 * increasing order, and the step into *step. Returns the number of ticks, or
 * -1 if lo, hi are not finite with lo < hi or max_intervals < 1. */
int lr_plot_ticks(double lo, double hi, int max_intervals, double *ticks, int cap,
                  double *step);

/* Labels for n ticks spaced by step, formatted alike so an axis reads
 * evenly: plain decimals with as many places as the step needs (0.005,
 * 2.5, 25000) unless that would be long (largest |tick| >= 1e5, or
 * step < 1e-4), then shortest scientific notation (1e-05, 2.5e+05). Zero is
 * "0", never "-0". */
void lr_plot_tick_labels(const double *ticks, int n, double step,
                         char (*labels)[LR_TICK_LABEL_MAX]);

#endif
