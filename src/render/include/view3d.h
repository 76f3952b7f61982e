/* view3d.h - 3D views of points, arrows, lines and boxes (the unit cube of
 * [N] Figs 5 and 11): a scene that is kept until it is drawn, so it can be
 * drawn through either backend with the same camera (an lr_view made by
 * lr_view_3d, layers.h).
 *
 *   - cairo (and any canvas that is not a GL one): the layers' orthographic
 *     projection in the order the items were added - painter's order, hidden
 *     cube edges dashed; exactly what layer_glyphs.c draws;
 *   - OSMesa or EGL: OpenGL with a depth buffer (canvas_gl_view3d.c): the same
 *     projection, points as shaded spheres, arrows as lines with shaded cone
 *     heads, lines and dashes as before, hidden surfaces removed by the
 *     depth test, antialiased by rendering 4 x 4 samples a pixel.
 *
 * Sizes that are pixels in the layers (line widths, dashes, point radii,
 * arrow heads) are pixels here too, at the view's scale. Each add call is
 * a "layer": where two layers' items coincide in depth (an exact normal
 * under a computed one), the later one is drawn on top, as painter's order
 * would. Text is drawn after the geometry (GL) or in order (cairo),
 * never hidden. */
#ifndef LAMINA_VIEW3D_H
#define LAMINA_VIEW3D_H

#include <stddef.h>
#include <stdint.h>

#include "layers.h"
#include "render.h"

typedef struct lr_scene3d lr_scene3d;

/* NULL on OOM. */
lr_scene3d *lr_scene3d_new(void);
void lr_scene3d_free(lr_scene3d *s);
/* Items held (a box, an arrow, a point, a text count one each). */
size_t lr_scene3d_count(const lr_scene3d *s);

/* The adders mirror layers.h; points are p[a][i], a < 3. Non-finite
 * points (and zero directions, for arrows) are skipped. They return 0, or
 * -1 when memory runs out (the scene keeps what it had). */
int lr_scene3d_circles(lr_scene3d *s, size_t n, const double *const p[3],
                       double radius_px, double width, lr_rgba colour);
int lr_scene3d_dots(lr_scene3d *s, size_t n, const double *const p[3],
                    double radius_px, lr_rgba colour);
int lr_scene3d_asterisk(lr_scene3d *s, const double p[3], double size_px,
                        double width, lr_rgba colour);
int lr_scene3d_arrows(lr_scene3d *s, size_t n, const double *const p[3],
                      const double *const d[3], double length, double width,
                      double head_px, lr_rgba colour, double dash);
int lr_scene3d_polyline(lr_scene3d *s, size_t n, const double *const p[3],
                        double width, lr_rgba colour, double dash);
int lr_scene3d_line(lr_scene3d *s, const double a[3], const double b[3],
                    double width, lr_rgba colour, double dash);
int lr_scene3d_box(lr_scene3d *s, const double lo[3], const double hi[3],
                   double width, lr_rgba colour);
/* Text anchored at world point p, moved by dx, dy pixels. */
int lr_scene3d_text(lr_scene3d *s, const double p[3], double dx, double dy,
                    double size, lr_rgba colour, lr_align align,
                    const char *text);

/* Many points (a 3D frame's particles, 10^6 and more) as shaded spheres
 * of radius_px, each in colours[i] (NULL: all in colour). Kept as floats;
 * through OpenGL they are splatted on the CPU into the depth buffer
 * (view3d_cloud.c: one primitive a point costs llvmpipe a quarter of a
 * microsecond), through cairo drawn as discs, far ones first. */
int lr_scene3d_cloud(lr_scene3d *s, size_t n, const double *const p[3],
                     const lr_rgba *colours, lr_rgba colour, double radius_px);
/* The same with colours packed as straight RGBA8, red in the low byte
 * (lr_rgba_pack): 4 bytes a point instead of 32, for 10^6 of them. */
int lr_scene3d_cloud_rgba8(lr_scene3d *s, size_t n, const double *const p[3],
                           const uint32_t *rgba8, double radius_px);
/* A colour as straight RGBA8, red in the low byte, each channel clamped
 * to [0, 1] and rounded. */
uint32_t lr_rgba_pack(lr_rgba k);
/* n triangles, vertex j of triangle k at xyz[9 k + 3 j .. + 2]; normals
 * in the same layout shade them (either side; NULL: flat colour); colours
 * per vertex (3 n, NULL: colour). Triangles with some alpha below 1 are
 * see-through: drawn after everything opaque, far ones first, without
 * hiding what is behind. cairo fills each with its vertices' mean
 * colour, far ones first. */
int lr_scene3d_triangles(lr_scene3d *s, size_t n, const double *xyz,
                         const double *normals, const lr_rgba *colours,
                         lr_rgba colour);

/* Draws the scene onto c through c's backend with the 3D view v; the
 * view's clip rectangle, when set, bounds the OpenGL drawing. -1 with a
 * message when v is not 3D, memory runs out or OpenGL fails. */
int lr_scene3d_draw(lr_canvas *c, const lr_view *v, const lr_scene3d *s,
                    char *err, size_t errlen);

/* Straight RGBA8 (rows top to bottom) src, sw x sh, composited OVER dst
 * (dw x dh) with its top-left at dst pixel (x, y); the part outside dst is
 * left out. */
void lr_rgba_over(unsigned char *dst, int dw, int dh, const unsigned char *src,
                  int sw, int sh, int x, int y);

#endif
