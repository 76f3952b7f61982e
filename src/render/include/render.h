/* render.h - lamina's drawing: a small canvas interface, PNG output, frames.
 *
 * Nothing here knows about the engine: a frame is described by plain arrays
 * (lr_frame), so the renderer can be tested alone and later issues can add
 * layers (phi contours, normal arrows, colour maps) and a second backend
 * (OSMesa, then EGL) behind the same lr_canvas calls.
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

/* Writes drawn pixels (RGBA8, rows top-down) in the format the path names
 * (lr_format_of): PNG through lr_png_write; for a .svg or .pdf name -1,
 * "cannot write 'PATH': ...", since vector files are drawn, not made from
 * pixels (lr_canvas_vector_new). The writer of frames, plots and figures
 * (image_write.c). */
int lr_image_write(const char *path, int width, int height,
                   const unsigned char *rgba, const lr_text_chunk *text,
                   size_t ntext, char *err, size_t errlen);

/* Reads an 8-bit RGBA PNG (any PNG is converted to RGBA8). *rgba is malloc'd. */
int lr_png_read(const char *path, int *width, int *height,
                unsigned char **rgba, char *err, size_t errlen);

/* ---- backends (canvas.c; issues 5, 20) ---------------------------------
 *
 * The same lr_canvas calls draw through cairo (always built; vector output),
 * OSMesa (software OpenGL; built when pkg-config finds osmesa, then
 * LAMINA_HAVE_OSMESA is defined) or EGL (OpenGL on EGL's surfaceless
 * platform; built when pkg-config finds egl, then LAMINA_HAVE_EGL). The two
 * GL backends share their drawing code (LAMINA_HAVE_GL: either is built).
 * All take pixel coordinates with the origin top-left, y down, and give
 * straight RGBA8 rows top to bottom. */

typedef enum lr_backend {
    LR_BACKEND_CAIRO = 0,
    LR_BACKEND_OSMESA = 1,
    LR_BACKEND_EGL = 2
} lr_backend;
#define LR_BACKEND_COUNT 3

/* "cairo", "osmesa", "egl" into *b, or "gl": EGL when it is built and
 * starts here (lr_backend_check), else OSMesa when built, else EGL (whose
 * check then says what to install). -1 with "unknown backend 'x' (known:
 * cairo, osmesa, egl, gl)" otherwise. Apart from "gl", does not check that
 * the backend was built. */
int lr_backend_parse(const char *name, lr_backend *b, char *err, size_t errlen);
const char *lr_backend_name(lr_backend b);
/* 0 if this build has backend b and it can start here (EGL: a display and
 * a context, tried once per process), else -1 with "this lamina was built
 * without X (install PACKAGE ...)" or "EGL cannot start: why". */
int lr_backend_check(lr_backend b, char *err, size_t errlen);
/* A raster canvas of any backend (a GL one fails cleanly in a build
 * without it). Sizes: 1..LR_CANVAS_MAX_SIZE each side, and the GL
 * implementation's own maximum, which it reports. */
#define LR_CANVAS_MAX_SIZE 16384
lr_canvas *lr_canvas_new(lr_backend b, int width, int height, char *err, size_t errlen);
lr_canvas *lr_canvas_osmesa_new(int width, int height, char *err, size_t errlen);
lr_canvas *lr_canvas_egl_new(int width, int height, char *err, size_t errlen);
lr_backend lr_canvas_backend(const lr_canvas *c);

/* Vector output through cairo: a canvas that draws into an SVG or PDF file
 * (atomically: into a temporary beside `path`, renamed by lr_canvas_finish;
 * lr_canvas_free without a successful finish removes it). width x height
 * is the page size in points (1 px = 1 pt). lr_canvas_read_rgba returns
 * NULL for these. `text` becomes the PDF's metadata (Creator, Subject,
 * Keywords from "Software", "lamina:script", "lamina:set"); SVG has none. */
typedef enum lr_format { LR_FORMAT_PNG = 0, LR_FORMAT_SVG, LR_FORMAT_PDF } lr_format;
/* By the file name's ending (.svg, .pdf, case-insensitive), else PNG. */
lr_format lr_format_of(const char *path);
lr_canvas *lr_canvas_vector_new(const char *path, lr_format format, int width,
                                int height, const lr_text_chunk *text, size_t ntext,
                                char *err, size_t errlen);
int lr_canvas_finish(lr_canvas *c, char *err, size_t errlen);

/* Filled polygons: npoly rings, ring k with counts[k] vertices, all vertices
 * in xy as x, y pairs (pixels). Nonzero winding, as cairo's default: rings
 * of one orientation unite, an opposite ring cuts a hole. */
void lr_canvas_fill(lr_canvas *c, size_t npoly, const size_t *counts,
                    const double *xy, lr_rgba colour);
/* Restricts drawing (clear too) to the pixel rectangle x, y, w, h (whole
 * pixels, clamped to the canvas); lr_canvas_unclip lifts it. */
void lr_canvas_clip(lr_canvas *c, int x, int y, int w, int h);
void lr_canvas_unclip(lr_canvas *c);
/* The advance width of text as lr_canvas_text draws it at size px. Needs no
 * canvas: every backend draws text with the same face (font.c). */
double lr_text_width(double size, const char *text);

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
    lr_backend backend;           /* 0 (memset): cairo */
} lr_frame;

/* The colour of group g (a fixed, colour-blind-safe palette, cycled). */
lr_rgba lr_palette(int g);

/* Draws the frame with f->backend and writes it to `path`: PNG, or SVG /
 * PDF (cairo only) when the name ends so. */
int lr_frame_write(const lr_frame *f, const char *path, char *err, size_t errlen);

/* Frees cairo's and fontconfig's static caches; call once at exit. */
void lr_shutdown(void);

#endif
