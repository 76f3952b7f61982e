/* layers.h - drawing layers for figures of points, normals and phi:
 * a view (a world window fitted into a pixel rectangle, or an orthographic
 * projection of a 3D box), phi contours by marching squares, open circles
 * for membrane points, an asterisk for the random point, arrows for normals
 * (computed solid, exact dashed), element and cube outlines.
 *
 * Everything is drawn through render.h's lr_canvas calls (lines and text),
 * so the layers work on any canvas backend. Nothing here knows about the
 * engine: inputs are plain arrays. */
#ifndef LAMINA_LAYERS_H
#define LAMINA_LAYERS_H

#include <stddef.h>

#include "render.h"

/* ---- views (layer_view.c) ----------------------------------------------- */

typedef struct lr_view {
    int is3d;
    double s;                 /* pixels per world unit */
    double ox, oy;            /* pixel of world (0,0) in 2D; of c in 3D */
    double c[3];              /* 3D: world point drawn at (ox, oy) */
    double right[3], up[3];   /* 3D: screen axes in world coordinates */
    double toward[3];         /* 3D: unit vector towards the viewer */
    double persp;             /* 3D: > 0, a perspective view from the eye
                                 this far from c along toward (pixels
                                 scale by persp / (persp - depth)); 0:
                                 orthographic (lr_view_3d's) */
    double clip[4];           /* pixels x0, y0, x1, y1 the layers draw in;
                                 x1 <= x0: no clipping (the default) */
} lr_view;

/* World window [wx0, wx1] x [wy0, wy1] into the pixel rectangle at (px, py)
 * of size pw x ph, one scale for both axes (circles stay circles),
 * centred; world y up. */
void lr_view_2d(lr_view *v, double px, double py, double pw, double ph,
                double wx0, double wy0, double wx1, double wy1);
/* Orthographic view of the box lo..hi seen from azimuth (degrees about z,
 * from +x) and elevation (degrees above the xy plane), fitted into the
 * pixel rectangle. */
void lr_view_3d(lr_view *v, double px, double py, double pw, double ph,
                const double lo[3], const double hi[3], double azimuth,
                double elevation);
/* Pixel position of world point p (p[2] ignored in 2D). */
void lr_view_map(const lr_view *v, const double p[3], double *x, double *y);
/* Where a 3D view's axis names go off the box (lamina.figure's panel
 * axes = "outside"): for axis a, at[a] is the middle of an edge along a
 * on the outline of the projected box (the lower one for x and y, the
 * left one for z) and out[a] the unit pixel direction from the box's
 * centre to it, to move the name along. */
void lr_view_axis_places(const lr_view *v, const double lo[3], const double hi[3],
                         double at[3][3], double out[3][2]);
/* Layers draw inside this pixel rectangle only (a panel of a figure). */
void lr_view_clip(lr_view *v, double x0, double y0, double x1, double y1);
/* Moves the view (and its clip rectangle) by dx, dy pixels: the same
 * picture on a canvas whose origin is elsewhere (a panel drawn alone). */
void lr_view_offset(lr_view *v, double dx, double dy);
/* A line in pixels, clipped to the view's rectangle (Liang-Barsky). */
void lr_view_line(lr_canvas *c, const lr_view *v, double ax, double ay, double bx,
                  double by, double width, lr_rgba colour, double dash);

/* ---- contours (layer_contour.c) ------------------------------------------ */

typedef void (*lr_segment_fn)(void *ctx, double x0, double y0, double x1,
                              double y1);
/* Marching squares on f, (nx+1) x (ny+1) samples, row-major in x (f[i +
 * (nx+1) j]). Emits the segments of the contour f = level in sample-index
 * coordinates (i, j); saddle cells are resolved by the cell-centre average;
 * cells with a non-finite corner are skipped. Returns the segment count. */
size_t lr_marching_squares(const double *f, int nx, int ny, double level,
                           lr_segment_fn emit, void *ctx);
/* Draws that contour, the samples spanning the world box x0..x1, y0..y1. */
size_t lr_layer_contour(lr_canvas *c, const lr_view *v, const double *f,
                        int nx, int ny, double x0, double y0, double x1,
                        double y1, double level, double width, lr_rgba colour);

/* ---- glyphs (layer_glyphs.c) --------------------------------------------- */

/* Points as p[a][i], a < dim (dim 2 or 3). */
void lr_layer_circles(lr_canvas *c, const lr_view *v, size_t n, int dim,
                      const double *const p[3], double radius_px, double width,
                      lr_rgba colour);
void lr_layer_dots(lr_canvas *c, const lr_view *v, size_t n, int dim,
                   const double *const p[3], double radius_px, lr_rgba colour);
/* An asterisk of three strokes, size_px across. */
void lr_layer_asterisk(lr_canvas *c, const lr_view *v, const double p[3],
                       double size_px, double width, lr_rgba colour);
/* Arrows from p_i along unit d_i, length in world units; the head is drawn
 * in pixels (head_px long). dash > 0: dashed shaft (exact normals). Zero
 * directions are skipped. */
void lr_layer_arrows(lr_canvas *c, const lr_view *v, size_t n, int dim,
                     const double *const p[3], const double *const d[3],
                     double length, double width, double head_px,
                     lr_rgba colour, double dash);
/* A rectangle (2D view) or the 12 edges of a box (3D view: edges behind
 * both faces that meet there are dashed). */
void lr_layer_box(lr_canvas *c, const lr_view *v, const double lo[3],
                  const double hi[3], double width, lr_rgba colour);
/* A polyline through n world points (2D: p[2] unused). */
void lr_layer_polyline(lr_canvas *c, const lr_view *v, size_t n, int dim,
                       const double *const p[3], double width, lr_rgba colour,
                       double dash);

#endif
