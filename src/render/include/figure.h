/* figure.h - a frame as a figure (docs/design.md, "Rendering"): a list of
 * panels, each a world window with a stack of layers - grid, filled
 * contours, particles (by body or by a scalar through a colour map),
 * curves, arrows - optionally mirrored (quarter-symmetric results shown
 * whole) or split left/right between two runs or two methods; titles, a
 * time label, colour bars and scale bars; drawn through either canvas
 * backend, written as PNG, or SVG / PDF through cairo.
 *
 * lr_frame_write (render.h) is the one-panel case of lr_figure_write and
 * draws exactly the pixels it always drew.
 *
 * Like render.h: plain arrays in, nothing known about the engine; errors
 * are values (0, or -1 with a one-line message in err[errlen]). */
#ifndef LAMINA_FIGURE_H
#define LAMINA_FIGURE_H

#include <stddef.h>

#include "render.h"

/* ---- colour maps (figure_colormap.c) ------------------------------------ */

typedef enum lr_cmap {
    LR_CMAP_VIRIDIS = 0,    /* sequential, perceptually even (default) */
    LR_CMAP_RDBU            /* diverging: blue below the middle, red above */
} lr_cmap;

/* "viridis" or "rdbu"; -1 with "unknown colour map 'x' (known: ...)". */
int lr_cmap_parse(const char *name, lr_cmap *m, char *err, size_t errlen);
const char *lr_cmap_name(lr_cmap m);
/* The colour at t in [0, 1] (clamped); NaN gives mid grey. */
lr_rgba lr_cmap_colour(lr_cmap m, double t);

/* ---- layers ------------------------------------------------------------- */

typedef struct lr_points {      /* particles as discs */
    size_t n;
    const double *x, *y;        /* world positions */
    const int *group;           /* palette colour per point; NULL: group 0 */
    const double *value;        /* non-NULL: colour by value through the
                                   panel's colour map instead */
    double radius;              /* world units, drawn at least 1 px */
    const double *group_radius; /* non-NULL: the radius of group g, for the
                                   points whose group is below ngroups */
    int ngroups;
    double band;                /* pixels; > 0 (with next): a band this wide
                                   over the discs from each point i to point
                                   next[i], each half in its own point's
                                   colour (a membrane's colour read along it) */
    const long *next;           /* next[i] >= 0: the point i is joined to;
                                   < 0: none */
} lr_points;

typedef struct lr_curve {       /* a polyline through world points */
    size_t n;
    const double *x, *y;
    int closed;
    double width;               /* pixels */
    double dash;                /* pixels, 0: solid */
    lr_rgba colour;
    int pairs;                  /* 1: points (2k, 2k+1) are separate
                                   segments (contour lines), not a polyline */
} lr_curve;

typedef struct lr_arrows {      /* arrows from (x, y) along unit (ux, uy) */
    size_t n;
    const double *x, *y, *ux, *uy;
    double length;              /* world units */
    double width, head;         /* shaft width and head length, pixels */
    double dash;                /* shaft dashes, pixels; 0: solid */
    lr_rgba colour;
    double thin;                /* pixels; > 0 with spacing > 0: only every
                                   k-th arrow, k the smallest with k spacing
                                   >= thin pixels, each k spacing long (the
                                   arrows' own gap, so none fuse; length is
                                   then unused) */
    double spacing;             /* world distance between consecutive arrows */
} lr_arrows;

typedef struct lr_field {       /* filled contours of a sampled field */
    const double *f;            /* (nx+1) x (ny+1) samples, x fastest */
    int nx, ny;
    double x0, y0, x1, y1;      /* the world box the samples span */
    const double *levels;       /* region f >= levels[k] is filled ... */
    int nlevels;
    const lr_rgba *colours;     /* ... with colours[k], or NULL: the panel's
                                   colour map at levels[k] */
} lr_field;

typedef struct lr_layers {      /* what one side of a panel shows */
    const lr_grid *grid;        /* NULL: none */
    const lr_field *fields;
    size_t nfields;
    const lr_points *points;
    size_t npoints;
    const lr_curve *curves;
    size_t ncurves;
    const lr_arrows *arrows;
    size_t narrows;
    const char *name;           /* a split panel names its halves */
} lr_layers;

/* ---- panels and figures ------------------------------------------------- */

typedef struct lr_panel {
    double wx0, wy0, wx1, wy1;  /* world window as shown (mirror copies
                                   included: see lr_panel_mirror_window) */
    int mirror_x, mirror_y;     /* also draw x -> 2 mirror_ax - x, and/or
                                   y -> 2 mirror_ay - y (and both) */
    double mirror_ax, mirror_ay;
    lr_layers side[2];          /* side[0] everywhere, or left of split_x */
    int split;                  /* side[1] right of split_x */
    double split_x;             /* world x of the split line */
    const char *title;          /* above the panel; NULL: none */
    lr_cmap cmap;               /* for values */
    double vmin, vmax;          /* value range; vmax <= vmin: the data's */
    int colourbar;              /* 1: a colour bar beside the panel */
    const char *colourbar_label;
    double scalebar;            /* world length; 0: none; < 0: a round length
                                   about a fifth of the window */
    const char *units;          /* after the scale bar's length; may be NULL */
} lr_panel;

/* The window w = {x0, y0, x1, y1} grown to hold its mirror images. */
void lr_panel_mirror_window(const lr_panel *p, double w[4]);
/* The value range a panel's colours span (and its colour bar shows): its
 * own range if set, else its coloured points' (symmetric about 0 for a
 * diverging map), never empty. */
void lr_panel_value_range(const lr_panel *p, double *lo, double *hi);

typedef struct lr_figure {
    int width, height;          /* pixels (points for SVG / PDF) */
    lr_backend backend;
    const lr_panel *panels;
    size_t npanels;             /* at least 1 */
    int rows, cols;             /* grid of panels; 0, 0: one row */
    const char *title;          /* top, centred */
    const char *label;          /* bottom-left, e.g. "t = 0.5000   step 500" */
    const lr_text_chunk *text;  /* provenance: PNG tEXt, PDF metadata */
    size_t ntext;
} lr_figure;

/* Draws the figure onto c (whose size must be the figure's). */
int lr_figure_draw(const lr_figure *f, lr_canvas *c, char *err, size_t errlen);

/* Draws and writes it: PNG (either backend), SVG or PDF (cairo) by the
 * file name's ending. Atomic; missing folders are created. */
int lr_figure_write(const lr_figure *f, const char *path, char *err, size_t errlen);

/* Pixels of the figure through its backend (what lr_figure_write writes
 * to PNG); malloc'd straight RGBA8, or NULL with err set. */
unsigned char *lr_figure_render(const lr_figure *f, char *err, size_t errlen);

#endif
