/* canvas_backend.h - what a canvas backend implements (private to
 * src/render).
 *
 * An lr_canvas is a base struct that every backend embeds as its first
 * member; canvas.c forwards each public lr_canvas_* call through the ops
 * table after the checks every backend would repeat (NULL canvas, non-finite
 * numbers), so a backend sees only drawable input. */
#ifndef LAMINA_CANVAS_BACKEND_H
#define LAMINA_CANVAS_BACKEND_H

#include <cairo.h>

#include "render.h"

typedef struct lr_canvas_ops {
    lr_backend backend;
    void (*destroy)(lr_canvas *c);
    void (*clear)(lr_canvas *c, lr_rgba colour);
    void (*line)(lr_canvas *c, double x0, double y0, double x1, double y1,
                 double width, lr_rgba colour, double dash);
    void (*rect)(lr_canvas *c, double x, double y, double w, double h,
                 double line_width, lr_rgba stroke);
    void (*discs)(lr_canvas *c, size_t n, const double *px, const double *py,
                  double r, const lr_rgba *colours);
    /* text is valid UTF-8 (canvas.c cleans it) and not empty */
    void (*text)(lr_canvas *c, double x, double y, double size, lr_rgba colour,
                 lr_align align, const char *text);
    void (*fill)(lr_canvas *c, size_t npoly, const size_t *counts,
                 const double *xy, lr_rgba colour);
    /* the rectangle is already clamped to the canvas and not empty;
     * w = 0: no clip; w < 0: an empty clip (nothing is drawn) */
    void (*clip)(lr_canvas *c, int x, int y, int w, int h);
    unsigned char *(*read_rgba)(lr_canvas *c);
    /* vector canvases only (NULL otherwise) */
    int (*finish)(lr_canvas *c, char *err, size_t errlen);
} lr_canvas_ops;

struct lr_canvas {
    const lr_canvas_ops *ops;
    int width, height;
    size_t charged;   /* bytes counted against the memory cap (lr_canvas_charge) */
};

/* A raster canvas's pixels (4 bytes each) counted against the process's
 * memory cap (src/util/lu_budget.c, issue 31 item 5), before they are
 * allocated: 0, or -1 with "cannot create a W x H canvas: memory limit ..."
 * in err. lr_canvas_free gives c->charged back. */
int lr_canvas_charge(int width, int height, size_t *charged, char *err, size_t errlen);

/* ---- shared by the backends ------------------------------------------- */

/* A copy of text that cairo accepts: every byte that is not part of valid
 * UTF-8 (cairo's notion: no surrogates, no noncharacters) becomes '?'.
 * malloc'd; NULL on OOM. Labels come from user scripts, and one bad byte
 * must not poison a cairo context (its errors are sticky). */
char *lr_utf8_clean(const char *text);

/* The face and font options every backend draws text with (font.c):
 * the bundled DejaVu Sans, hinting off, greyscale antialiasing. Sets them
 * on cr; -1 if cairo is in an error state afterwards. */
int lr_font_setup(cairo_t *cr);
/* Drops the cached face; lr_shutdown calls it before cairo's own reset. */
void lr_font_release(void);

/* Makes no GL context current and destroys the ones kept for the next
 * canvas (canvas_gl.c; nothing without GL); lr_shutdown calls it. */
void lr_canvas_gl_release(void);

/* 0 if EGL starts here (a display, a context, a pixel read back), tried
 * once per process; else -1 with "EGL cannot start: why" (canvas_egl.c). */
int lr_canvas_egl_probe(char *err, size_t errlen);

#endif
