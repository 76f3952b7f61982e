/* render.h - lamina's drawing: a small canvas interface, PNG output, frames.
 *
 * Nothing here knows about the engine: a frame is described by plain arrays
 * (lr_frame), so the renderer can be tested alone and later issues can add
 * layers (phi contours, normal arrows, colour maps) and a second backend
 * (OSMesa) behind the same lr_canvas calls.
 *
 * Errors are values: every function that can fail returns 0 on success and
 * -1 on failure with a one-line message written into err[errlen]. */
#ifndef LAMINA_RENDER_H
#define LAMINA_RENDER_H

#include <stddef.h>

typedef struct lr_rgba { double r, g, b, a; } lr_rgba;   /* 0..1 each */

/* ---- canvas: pixel coordinates, origin top-left, y down ---------------- */

typedef struct lr_canvas lr_canvas;

typedef enum lr_align { LR_ALIGN_LEFT, LR_ALIGN_CENTER, LR_ALIGN_RIGHT } lr_align;

lr_canvas *lr_canvas_cairo_new(int width, int height, char *err, size_t errlen);
void lr_canvas_free(lr_canvas *c);
int  lr_canvas_width(const lr_canvas *c);
int  lr_canvas_height(const lr_canvas *c);
void lr_canvas_clear(lr_canvas *c, lr_rgba colour);
/* dash = 0: solid; dash > 0: dash length in pixels */
void lr_canvas_line(lr_canvas *c, double x0, double y0, double x1, double y1,
                    double width, lr_rgba colour, double dash);
void lr_canvas_rect(lr_canvas *c, double x, double y, double w, double h,
                    double line_width, lr_rgba stroke);
/* n filled discs of radius r (pixels), one colour each (colours[i]). */
void lr_canvas_discs(lr_canvas *c, size_t n, const double *px, const double *py,
                     double r, const lr_rgba *colours);
/* baseline-anchored text, size in pixels, bundled/fixed font, hinting off */
void lr_canvas_text(lr_canvas *c, double x, double y, double size,
                    lr_rgba colour, lr_align align, const char *text);
/* Straight (not premultiplied) RGBA8, rows top to bottom, stride = 4*width.
 * The returned buffer is malloc'd and owned by the caller. NULL on OOM. */
unsigned char *lr_canvas_read_rgba(lr_canvas *c);

/* ---- PNG ------------------------------------------------------------- */

typedef struct lr_text_chunk { const char *key, *value; } lr_text_chunk;

/* Writes an 8-bit RGBA PNG through libpng, atomically: into a temporary file
 * beside `path`, then rename(2). On any failure the temporary is removed and
 * `path` is untouched. Missing parent directories are created. `text` chunks
 * (provenance: program version, script, parameters) are stored as tEXt. */
int lr_png_write(const char *path, int width, int height,
                 const unsigned char *rgba, const lr_text_chunk *text,
                 size_t ntext, char *err, size_t errlen);

/* Reads an 8-bit RGBA PNG (any PNG is converted to RGBA8). *rgba is malloc'd. */
int lr_png_read(const char *path, int *width, int *height,
                unsigned char **rgba, char *err, size_t errlen);

/* ---- frames ---------------------------------------------------------- */

typedef struct lr_grid {
    double x0, y0;        /* first node */
    double hx, hy;        /* cell size */
    int nx, ny;           /* cells */
} lr_grid;

typedef struct lr_frame {
    int width, height;            /* pixels */
    double wx0, wy0, wx1, wy1;    /* world window; aspect ratio is kept,
                                     the window centred, the rest margin */
    const lr_grid *grid;          /* NULL: no grid lines */
    size_t n;                     /* particles */
    const double *x, *y;          /* world positions */
    const int *group;             /* colour index (body) per particle */
    double radius;                /* particle radius in world units
                                     (drawn at least 1 px) */
    const char *label;            /* e.g. "t = 0.5000", bottom-left; may be NULL */
    const char *title;            /* top, centred; may be NULL */
    const lr_text_chunk *text;    /* provenance, into the PNG */
    size_t ntext;
} lr_frame;

/* The colour of group g (a fixed, colour-blind-safe palette, cycled). */
lr_rgba lr_palette(int g);

/* Draws the frame with cairo and writes it to `path` (PNG). */
int lr_frame_write(const lr_frame *f, const char *path, char *err, size_t errlen);

/* Frees cairo's and fontconfig's static caches; call once at exit. */
void lr_shutdown(void);

#endif
