/* figure_internal.h - shared by figure*.c (not a public header). */
#ifndef LAMINA_FIGURE_INTERNAL_H
#define LAMINA_FIGURE_INTERNAL_H

#include "figure.h"

/* Colours of the figure furniture (frame.c's, kept). */
extern const lr_rgba LR_FIG_BACKGROUND, LR_FIG_GRID, LR_FIG_OUTLINE, LR_FIG_TEXT;

/* A panel's world window fitted into pixels: one scale for x and y, world
 * y up, pixel y down. */
typedef struct fig_view {
    double s;                   /* pixels per world unit */
    double ox, oy;              /* pixel position of the world origin */
    double wx0, wy0, wx1, wy1;  /* the window */
} fig_view;

static inline void fig_to_pixel(const fig_view *v, double x, double y,
                                double *px, double *py)
{
    *px = v->ox + v->s * x;
    *py = v->oy - v->s * y;
}

/* One mirror copy: x -> 2 ax - x when fx, y -> 2 ay - y when fy. */
typedef struct fig_mirror {
    int fx, fy;
    double ax, ay;
} fig_mirror;

static inline double fig_mx(const fig_mirror *m, double x)
{
    return m->fx ? 2.0 * m->ax - x : x;
}
static inline double fig_my(const fig_mirror *m, double y)
{
    return m->fy ? 2.0 * m->ay - y : y;
}

/* Outline sides a grid copy leaves out (they lie on a mirror axis). */
enum { FIG_SKIP_LEFT = 1, FIG_SKIP_RIGHT = 2, FIG_SKIP_BOTTOM = 4, FIG_SKIP_TOP = 8 };

/* figure.c: a drawing's pixels through backend b - a w x h canvas,
 * draw(ctx, canvas, ...), the pixels read back (lr_figure_render's and
 * lr_figure3d_render's one path); malloc'd straight RGBA8, or NULL with
 * err set. */
typedef int (*fig_draw_fn)(const void *ctx, lr_canvas *c, char *err, size_t errlen);
unsigned char *fig_render(lr_backend b, int w, int h, fig_draw_fn draw, const void *ctx,
                          char *err, size_t errlen);
/* figure.c: the refusals lr_figure_* and lr_figure3d_* share, each message
 * after `what` ("" or "3D frame: "): 0, or -1 with `problem` (what is
 * wrong with a figure; NULL: nothing) in err; 0, or -1 when canvas c is
 * missing or not w x h. */
int fig_refuse(const char *what, const char *problem, char *err, size_t errlen);
int fig_canvas_fits(const char *what, const lr_canvas *c, int w, int h, char *err,
                    size_t errlen);
/* figure_layers.c */
void fig_draw_grid(lr_canvas *c, const fig_view *v, const lr_grid *g, int skip);
/* The value range of the panel's value-coloured points, for auto ranges;
 * 0 if there are none. */
int fig_value_range(const lr_panel *p, double *lo, double *hi);
int fig_draw_points(lr_canvas *c, const fig_view *v, const fig_mirror *m,
                    const lr_points *pts, const lr_panel *p, double vmin, double vmax);
void fig_draw_curve(lr_canvas *c, const fig_view *v, const fig_mirror *m,
                    const lr_curve *cv);
int fig_draw_arrows(lr_canvas *c, const fig_view *v, const fig_mirror *m,
                    const lr_arrows *a);

/* figure_fill.c */
int fig_draw_field(lr_canvas *c, const fig_view *v, const fig_mirror *m,
                   const lr_field *fd, const lr_panel *p, double vmin, double vmax);

/* figure_bars.c */
/* Width of the colour bar strip (bar, ticks, labels) for font size font. */
double fig_colourbar_width(const lr_panel *p, double font, double vmin, double vmax);
void fig_draw_colourbar(lr_canvas *c, const lr_panel *p, double x, double y0,
                        double y1, double font, double vmin, double vmax);
void fig_draw_scalebar(lr_canvas *c, const fig_view *v, const lr_panel *p,
                       double font);

#endif
