/* canvas_cairo.c - the lr_canvas interface over a cairo ARGB32 image
 * surface, or over an SVG / PDF surface for vector output.
 *
 * Every drawing call is void (the interface is shared with the OSMesa
 * backend, which cannot fail per call); cairo keeps a sticky error status
 * instead, and lr_canvas_read_rgba / lr_canvas_finish report it, so a frame
 * is never written from a half-drawn surface. Because that status is
 * sticky, inputs that would put cairo into an error state (invalid UTF-8,
 * non-finite coordinates) are filtered before they get here (canvas.c). */
#include "atomic_file.h"
#include "canvas_backend.h"

#include <cairo-pdf.h>
#include <cairo-svg.h>
#include <cairo.h>
#include <errno.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "util.h"

/* Sub-pixel positions per axis a stamped disc can take: at most 1/8 px
 * off, which no one sees. */
#define STAMP_PHASES 4

typedef struct cc_canvas {
    lr_canvas base;
    cairo_surface_t *surface;
    cairo_t *cr;
    int width, height;
    cairo_surface_t *stamps;    /* disc coverage masks, NULL until needed */
    double stamp_r;             /* the radius they were drawn for */
    int stamp_reach, stamp_size;
    /* each mask's covered pixels, in row order: offset (dy * stride_px +
     * dx, rebuilt for the surface's stride) and coverage; tile q's run is
     * cov_at[q] .. cov_at[q + 1] (see "discs") */
    int *cov_off;
    unsigned char *cov_val;
    int cov_at[STAMP_PHASES * STAMP_PHASES + 1];
    int cov_stride;             /* the surface stride the offsets are for */
    /* where stamped discs may write: the canvas, or the clip rectangle */
    int bx0, by0, bx1, by1;
    /* vector output: the file being written (lr_atomic), its state */
    int vector;
    lr_atomic out;
    int out_open;
    int write_errno;            /* of a failed write into out */
} cc_canvas;

static const lr_canvas_ops cairo_ops;

static cc_canvas *as_cairo(lr_canvas *c) { return (cc_canvas *)c; }

/* Discs per path fill: one fill per colour run, but bounded so that a long
 * run does not build a path of megabytes first. */
#define DISC_BATCH 1024

/* Discs up to this radius (pixels) are stamped, see "discs" below. */
#define STAMP_MAX_RADIUS 24.0


/* Below this radius an arc is slower than a pixel and looks no better. */
#define DISC_MIN_ARC_RADIUS 0.8

/* M_PI is not in strict C11 */
#define TWO_PI 6.283185307179586476925286766559

static cc_canvas *canvas_alloc(int width, int height)
{
    cc_canvas *c = calloc(1, sizeof *c);
    if (!c)
        return NULL;
    c->base.ops = &cairo_ops;
    c->base.width = c->width = width;
    c->base.height = c->height = height;
    c->bx1 = width;
    c->by1 = height;
    return c;
}

/* Creates the context on c->surface with lamina's font; cairo's status. */
static cairo_status_t canvas_start(cc_canvas *c)
{
    cairo_status_t st = cairo_surface_status(c->surface);
    if (st == CAIRO_STATUS_SUCCESS) {
        c->cr = cairo_create(c->surface);
        st = cairo_status(c->cr);
    }
    if (st == CAIRO_STATUS_SUCCESS && lr_font_setup(c->cr) != 0)
        st = cairo_status(c->cr) != CAIRO_STATUS_SUCCESS ? cairo_status(c->cr)
                                                         : CAIRO_STATUS_NO_MEMORY;
    if (st == CAIRO_STATUS_SUCCESS)
        cairo_set_antialias(c->cr, CAIRO_ANTIALIAS_DEFAULT);
    return st;
}

lr_canvas *lr_canvas_cairo_new(int width, int height, char *err, size_t errlen)
{
    if (width <= 0 || height <= 0 || width > 32767 || height > 32767) {
        char why[64];
        snprintf(why, sizeof why, "invalid size %dx%d (1..32767 each)", width,
                 height);
        lu_err(err, errlen, "%s: %s", "cannot create canvas", why);
        return NULL;
    }
    /* the size is named: "out of memory" alone does not say that a 16384
     * x 16384 image needs 1 GB (issue 18) */
    char what[64];
    snprintf(what, sizeof what, "cannot create a %d x %d canvas", width, height);
    size_t charged;
    if (lr_canvas_charge(width, height, &charged, err, errlen) != 0)
        return NULL;
    cc_canvas *c = canvas_alloc(width, height);
    if (!c) {
        lu_budget_release(LU_MEM_RENDER, charged);
        lu_err(err, errlen, "%s: %s", what, "out of memory");
        return NULL;
    }
    c->base.charged = charged;   /* lr_canvas_free gives it back */
    c->surface = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, width, height);
    cairo_status_t st = canvas_start(c);
    if (st != CAIRO_STATUS_SUCCESS) {
        lu_err(err, errlen, "%s: %s", what, cairo_status_to_string(st));
        lr_canvas_free(&c->base);
        return NULL;
    }
    return &c->base;
}

static void cc_destroy(lr_canvas *base)
{
    cc_canvas *c = as_cairo(base);
    /* cairo_destroy / cairo_surface_destroy accept NULL */
    cairo_destroy(c->cr);
    if (c->vector && c->surface)
        cairo_surface_finish(c->surface);   /* before the file goes */
    cairo_surface_destroy(c->surface);
    cairo_surface_destroy(c->stamps);
    free(c->cov_off);
    free(c->cov_val);
    if (c->out_open)
        lr_atomic_abort(&c->out, "not finished", NULL, 0);
    free(c);
}

/* ---- vector output ----------------------------------------------------- */

static cairo_status_t write_out(void *closure, const unsigned char *data,
                                unsigned int length)
{
    cc_canvas *c = closure;
    errno = 0;
    if (length && fwrite(data, 1, length, c->out.fp) != length) {
        c->write_errno = errno ? errno : EIO;
        return CAIRO_STATUS_WRITE_ERROR;
    }
    return CAIRO_STATUS_SUCCESS;
}

static const char *chunk(const lr_text_chunk *text, size_t ntext, const char *key)
{
    for (size_t i = 0; i < ntext; i++)
        if (text[i].key && strcmp(text[i].key, key) == 0)
            return text[i].value;
    return NULL;
}

/* PDF keeps provenance in its document information; cairo 1.16 stamps the
 * creation time too, which is replaced by a fixed one so that the same
 * frame gives the same bytes (like the PNGs, which carry no tIME). */
static void pdf_metadata(cairo_surface_t *s, const lr_text_chunk *text, size_t ntext)
{
    static const struct { const char *key; cairo_pdf_metadata_t field; } map[] = {
        { "Software", CAIRO_PDF_METADATA_CREATOR },
        { "lamina:script", CAIRO_PDF_METADATA_SUBJECT },
        { "lamina:set", CAIRO_PDF_METADATA_KEYWORDS },
    };
    for (size_t i = 0; i < sizeof map / sizeof map[0]; i++) {
        const char *v = chunk(text, ntext, map[i].key);
        if (v && *v)
            cairo_pdf_surface_set_metadata(s, map[i].field, v);
    }
    cairo_pdf_surface_set_metadata(s, CAIRO_PDF_METADATA_CREATE_DATE,
                                   "2000-01-01T00:00:00Z");
}

lr_canvas *lr_canvas_vector_new(const char *path, lr_format format, int width,
                                int height, const lr_text_chunk *text, size_t ntext,
                                char *err, size_t errlen)
{
    if (format != LR_FORMAT_SVG && format != LR_FORMAT_PDF) {
        lu_err(err, errlen, "%s: %s", "cannot create a vector canvas", "not SVG or PDF");
        return NULL;
    }
    if (width <= 0 || height <= 0 || width > LR_CANVAS_MAX_SIZE ||
        height > LR_CANVAS_MAX_SIZE) {
        char why[64];
        snprintf(why, sizeof why, "invalid size %dx%d (1..%d each)", width,
                 height, LR_CANVAS_MAX_SIZE);
        lu_err(err, errlen, "%s: %s", "cannot create canvas", why);
        return NULL;
    }
    cc_canvas *c = canvas_alloc(width, height);
    if (!c) {
        lu_err(err, errlen, "%s: %s", "cannot create canvas", "out of memory");
        return NULL;
    }
    c->vector = 1;
    if (lr_atomic_open(&c->out, path, err, errlen) != 0) {
        free(c);
        return NULL;
    }
    c->out_open = 1;
    if (format == LR_FORMAT_SVG)
        c->surface = cairo_svg_surface_create_for_stream(write_out, c, width, height);
    else
        c->surface = cairo_pdf_surface_create_for_stream(write_out, c, width, height);
    if (format == LR_FORMAT_PDF &&
        cairo_surface_status(c->surface) == CAIRO_STATUS_SUCCESS)
        pdf_metadata(c->surface, text, ntext);
    cairo_status_t st = canvas_start(c);
    if (st != CAIRO_STATUS_SUCCESS) {
        char why[256];
        snprintf(why, sizeof why, "cairo: %s", cairo_status_to_string(st));
        cairo_destroy(c->cr);
        c->cr = NULL;
        cairo_surface_destroy(c->surface);
        c->surface = NULL;
        c->out_open = 0;
        lr_atomic_abort(&c->out, why, err, errlen);
        free(c);
        return NULL;
    }
    return &c->base;
}

static int cc_finish(lr_canvas *base, char *err, size_t errlen)
{
    cc_canvas *c = as_cairo(base);
    if (!c->vector || !c->out_open) {
        lu_err(err, errlen, "%s: %s", "cannot finish", "not an open vector canvas");
        return -1;
    }
    cairo_status_t st = cairo_status(c->cr);
    cairo_destroy(c->cr);
    c->cr = NULL;
    cairo_surface_finish(c->surface);
    if (st == CAIRO_STATUS_SUCCESS)
        st = cairo_surface_status(c->surface);
    c->out_open = 0;
    if (st != CAIRO_STATUS_SUCCESS) {
        char why[256];
        snprintf(why, sizeof why, "%s", c->write_errno ? strerror(c->write_errno)
                                                       : cairo_status_to_string(st));
        return lr_atomic_abort(&c->out, why, err, errlen);
    }
    return lr_atomic_commit(&c->out, err, errlen);
}

/* ---- drawing ----------------------------------------------------------- */

static void set_colour(cairo_t *cr, lr_rgba k)
{
    cairo_set_source_rgba(cr, k.r, k.g, k.b, k.a);
}

/* A finished vector canvas has no context left to draw into. */
static int drawable(const cc_canvas *c) { return c->cr != NULL; }

/* The context of a drawing call, saved (the call restores it), or NULL
 * when there is nothing to draw into. */
static cairo_t *begin(lr_canvas *base)
{
    cc_canvas *c = as_cairo(base);
    if (!drawable(c))
        return NULL;
    cairo_save(c->cr);
    return c->cr;
}

static void cc_clear(lr_canvas *base, lr_rgba colour)
{
    cc_canvas *c = as_cairo(base);
    if (!drawable(c))
        return;
    /* SOURCE, not OVER: a translucent clear colour must replace, not blend */
    cairo_save(c->cr);
    cairo_set_operator(c->cr, CAIRO_OPERATOR_SOURCE);
    set_colour(c->cr, colour);
    cairo_paint(c->cr);
    cairo_restore(c->cr);
}

static int finite2(double a, double b) { return isfinite(a) && isfinite(b); }

static void cc_line(lr_canvas *base, double x0, double y0, double x1, double y1,
                       double width, lr_rgba colour, double dash)
{
    cairo_t *cr = begin(base);
    if (!cr)
        return;
    cairo_set_line_width(cr, width);
    cairo_set_line_cap(cr, CAIRO_LINE_CAP_BUTT);
    if (dash > 0 && isfinite(dash))
        cairo_set_dash(cr, &dash, 1, 0.0);
    set_colour(cr, colour);
    cairo_new_path(cr);
    cairo_move_to(cr, x0, y0);
    cairo_line_to(cr, x1, y1);
    cairo_stroke(cr);
    cairo_restore(cr);
}

static void cc_rect(lr_canvas *base, double x, double y, double w, double h,
                       double line_width, lr_rgba stroke)
{
    cairo_t *cr = begin(base);
    if (!cr)
        return;
    cairo_set_line_width(cr, line_width);
    cairo_set_line_join(cr, CAIRO_LINE_JOIN_MITER);
    set_colour(cr, stroke);
    cairo_new_path(cr);
    cairo_rectangle(cr, x, y, w, h);
    cairo_stroke(cr);
    cairo_restore(cr);
}

/* ---- discs ------------------------------------------------------------
 *
 * A million small discs through cairo's path filler cost seconds (every
 * arc is tessellated). Small discs are therefore stamped: cairo draws the
 * antialiased disc once into an A8 coverage mask for each of
 * STAMP_PHASES x STAMP_PHASES sub-pixel offsets, and each disc composites
 * its colour through the nearest mask straight into the surface (OVER,
 * premultiplied, integer arithmetic: deterministic). That bypasses the
 * cairo context, which is equivalent only because this canvas never sets
 * a transform and its only clips are whole-pixel rectangles, which the
 * stamps honour themselves (bx0..by1). Large discs, which are few and
 * cover many pixels, still go through cairo's paths, as do all discs of a
 * vector canvas (it has no pixels). */

static int same_colour(const lr_rgba *a, const lr_rgba *b)
{
    return a->r == b->r && a->g == b->g && a->b == b->b && a->a == b->a;
}

static void fill_run(cairo_t *cr, const lr_rgba *colour, size_t *in_path)
{
    if (*in_path == 0)
        return;
    set_colour(cr, *colour);
    cairo_fill(cr);
    *in_path = 0;
}

/* Culling also keeps far-away points out of cairo's fixed-point range. */
static int near_canvas(const cc_canvas *c, double x, double y, double reach)
{
    return finite2(x, y) && x + reach >= 0 && y + reach >= 0 &&
           x - reach <= c->width && y - reach <= c->height;
}

/* Path fill, one fill per colour run. Arcs are traced clockwise on screen,
 * so under the default winding rule overlapping discs unite. */
static void discs_filled(cc_canvas *c, size_t n, const double *px,
                         const double *py, double r, const lr_rgba *colours)
{
    cairo_t *cr = c->cr;
    const lr_rgba *run = NULL;
    size_t in_path = 0;
    cairo_save(cr);
    cairo_new_path(cr);
    for (size_t i = 0; i < n; i++) {
        if (!near_canvas(c, px[i], py[i], r))
            continue;
        if (!run || !same_colour(run, &colours[i]) || in_path == DISC_BATCH) {
            if (run)
                fill_run(cr, run, &in_path);
            run = &colours[i];
        }
        cairo_new_sub_path(cr);
        cairo_arc(cr, px[i], py[i], r, 0.0, TWO_PI);
        in_path++;
    }
    if (run)
        fill_run(cr, run, &in_path);
    cairo_restore(cr);
}

/* Builds (or keeps) the coverage masks for radius r; -1 on failure. The
 * mask for phase (qx, qy) is tile qy*STAMP_PHASES+qx, tiles stacked
 * vertically; its pixel (reach, reach) holds the disc centre's pixel. */
static int prepare_stamps(cc_canvas *c, double r)
{
    if (c->stamps && c->stamp_r == r)
        return 0;
    cairo_surface_destroy(c->stamps);
    c->stamps = NULL;
    c->cov_stride = 0;   /* the covered-pixel lists go with the masks */
    int reach = (int)ceil(r) + 1, size = 2 * reach + 1;
    int tiles = STAMP_PHASES * STAMP_PHASES;
    cairo_surface_t *m = cairo_image_surface_create(CAIRO_FORMAT_A8, size,
                                                    size * tiles);
    cairo_t *cr = cairo_create(m);   /* an error object if m is one */
    for (int q = 0; q < tiles; q++) {
        double fx = (q % STAMP_PHASES + 0.5) / STAMP_PHASES;
        double fy = (q / STAMP_PHASES + 0.5) / STAMP_PHASES;
        cairo_new_sub_path(cr);
        cairo_arc(cr, reach + fx, q * size + reach + fy, r, 0.0, TWO_PI);
    }
    cairo_fill(cr);
    cairo_status_t st = cairo_status(cr);
    cairo_destroy(cr);
    cairo_surface_flush(m);
    if (st != CAIRO_STATUS_SUCCESS ||
        cairo_surface_status(m) != CAIRO_STATUS_SUCCESS) {
        cairo_surface_destroy(m);
        return -1;
    }
    c->stamps = m;
    c->stamp_r = r;
    c->stamp_reach = reach;
    c->stamp_size = size;
    return 0;
}

/* x*y/255 rounded, exactly, for x, y in 0..255 */
static uint32_t mul255(uint32_t x, uint32_t y)
{
    uint32_t t = x * y + 128;
    return (t + (t >> 8)) >> 8;
}

/* A colour as premultiplied 8-bit channels: a, r, g, b. */
typedef struct argb8 { uint32_t ch[4]; } argb8;

static uint32_t to8(double v)
{
    return v <= 0 ? 0 : v >= 1 ? 255 : (uint32_t)lround(v * 255.0);
}

static argb8 premultiply(lr_rgba k)
{
    argb8 p;
    p.ch[0] = to8(k.a);
    p.ch[1] = mul255(to8(k.r), p.ch[0]);
    p.ch[2] = mul255(to8(k.g), p.ch[0]);
    p.ch[3] = mul255(to8(k.b), p.ch[0]);
    return p;
}

/* Composites colour k at coverage cov (1..255) OVER the pixel at dst. */
static void blend(unsigned char *dst, const argb8 *k, uint32_t cov)
{
    uint32_t d;
    memcpy(&d, dst, sizeof d);
    uint32_t keep = 255 - mul255(k->ch[0], cov), out = 0;
    for (int i = 0; i < 4; i++) {
        int shift = 24 - 8 * i;
        uint32_t v = mul255(k->ch[i], cov) + mul255((d >> shift) & 0xFF, keep);
        out |= v << shift;
    }
    memcpy(dst, &out, sizeof out);
}

/* mul255 on two 8-bit lanes at bits 0 and 16 at once: x*y + 128 stays
 * below 2^16 in each lane and so does t + (t >> 8), so no carry crosses a
 * lane and each lane is mul255's value, exactly. */
static uint32_t mul255_2(uint32_t x, uint32_t y)
{
    uint32_t t = x * y + 0x00800080u;
    t += (t >> 8) & 0x00FF00FFu;
    return (t >> 8) & 0x00FF00FFu;
}

/* blend(), two channels per multiply: the same sums to the last bit (each
 * channel's sum is at most 255, so none spills into its neighbour). ag and
 * rb are k's alpha-green and red-blue lanes. */
static void blend2(unsigned char *dst, uint32_t ag, uint32_t rb, uint32_t cov)
{
    uint32_t d;
    memcpy(&d, dst, sizeof d);
    uint32_t sag = mul255_2(ag, cov), srb = mul255_2(rb, cov);
    uint32_t keep = 255 - (sag >> 16);
    uint32_t out = (sag + mul255_2((d >> 8) & 0x00FF00FFu, keep)) << 8 |
                   (srb + mul255_2(d & 0x00FF00FFu, keep));
    memcpy(dst, &out, sizeof out);
}

/* Each mask's covered pixels as (offset in the surface, coverage), so that
 * a stamp wholly inside the canvas touches only them: built once per
 * radius and stride; -1 without memory (the caller then loops the mask). */
static int prepare_cover(cc_canvas *c, int istride)
{
    if (c->cov_stride == istride)
        return 0;
    int size = c->stamp_size, tiles = STAMP_PHASES * STAMP_PHASES;
    int mstride = cairo_image_surface_get_stride(c->stamps);
    const unsigned char *m = cairo_image_surface_get_data(c->stamps);
    size_t n = 0;
    for (int q = 0; q < tiles; q++)
        for (int j = 0; j < size; j++)
            for (int i = 0; i < size; i++)
                n += m[((size_t)q * size + j) * mstride + i] != 0;
    int *off = realloc(c->cov_off, (n ? n : 1) * sizeof *off);
    if (off) c->cov_off = off;
    unsigned char *val = realloc(c->cov_val, n ? n : 1);
    if (val) c->cov_val = val;
    if (!off || !val)
        return -1;
    n = 0;
    for (int q = 0; q < tiles; q++) {
        c->cov_at[q] = (int)n;
        for (int j = 0; j < size; j++)
            for (int i = 0; i < size; i++) {
                unsigned char v = m[((size_t)q * size + j) * mstride + i];
                if (!v) continue;
                off[n] = j * istride + 4 * i;
                val[n++] = v;
            }
    }
    c->cov_at[tiles] = (int)n;
    c->cov_stride = istride;
    return 0;
}

/* The phase bin of a coordinate's fractional part. */
static int phase(double frac)
{
    int q = (int)(frac * STAMP_PHASES);
    return q < 0 ? 0 : q >= STAMP_PHASES ? STAMP_PHASES - 1 : q;
}

static void stamp_disc(cc_canvas *c, unsigned char *img, int istride,
                       double x, double y, const argb8 *k)
{
    double fx = floor(x), fy = floor(y);
    int reach = c->stamp_reach, size = c->stamp_size;
    int x0 = (int)fx - reach, y0 = (int)fy - reach;
    int q = phase(y - fy) * STAMP_PHASES + phase(x - fx);
    int mstride = cairo_image_surface_get_stride(c->stamps);
    const unsigned char *tile = cairo_image_surface_get_data(c->stamps) +
                                (size_t)q * size * mstride;
    int j0 = y0 < c->by0 ? c->by0 - y0 : 0;
    int j1 = c->by1 - y0 < size ? c->by1 - y0 : size;
    int i0 = x0 < c->bx0 ? c->bx0 - x0 : 0;
    int i1 = c->bx1 - x0 < size ? c->bx1 - x0 : size;
    if (c->cov_stride == istride && j0 == 0 && i0 == 0 && j1 == size && i1 == size) {
        /* wholly inside: only the covered pixels, two channels a multiply */
        unsigned char *at = img + (size_t)y0 * istride + 4 * (size_t)x0;
        uint32_t ag = k->ch[0] << 16 | k->ch[2], rb = k->ch[1] << 16 | k->ch[3];
        for (int e = c->cov_at[q]; e < c->cov_at[q + 1]; e++)
            blend2(at + c->cov_off[e], ag, rb, c->cov_val[e]);
        return;
    }
    for (int j = j0; j < j1; j++) {
        const unsigned char *cov = tile + (size_t)j * mstride;
        /* from the first pixel inside the canvas: a stamp reaching past the
         * left edge (x0 < 0) must not form a pointer before the image
         * (UBSan, found by fuzzing: tests/fuzz) */
        unsigned char *row = img + (size_t)(y0 + j) * istride + 4 * (size_t)(x0 + i0);
        for (int i = i0; i < i1; i++)
            if (cov[i])
                blend(row + 4 * (size_t)(i - i0), k, cov[i]);
    }
}

/* Below DISC_MIN_ARC_RADIUS a disc is the pixel holding its centre, so
 * a dot stays crisp; otherwise a stamp from prepare_stamps. */
static void discs_stamped(cc_canvas *c, size_t n, const double *px,
                          const double *py, double r, const lr_rgba *colours)
{
    cairo_surface_flush(c->surface);
    unsigned char *img = cairo_image_surface_get_data(c->surface);
    int istride = cairo_image_surface_get_stride(c->surface);
    int dot = r < DISC_MIN_ARC_RADIUS;
    if (!dot)
        prepare_cover(c, istride);   /* on failure the masks are looped */
    const lr_rgba *last = NULL;
    argb8 k = { { 0, 0, 0, 0 } };
    for (size_t i = 0; i < n; i++) {
        double x = px[i], y = py[i];
        if (!near_canvas(c, x, y, dot ? 1.0 : r))
            continue;
        if (!last || !same_colour(last, &colours[i])) {
            last = &colours[i];
            k = premultiply(*last);
        }
        if (!dot) {
            stamp_disc(c, img, istride, x, y, &k);
        } else if (x >= c->bx0 && y >= c->by0 && x < c->bx1 && y < c->by1) {
            size_t at = (size_t)floor(y) * istride + 4 * (size_t)floor(x);
            blend(img + at, &k, 255);
        }
    }
    cairo_surface_mark_dirty(c->surface);
}

static void cc_discs(lr_canvas *base, size_t n, const double *px,
                        const double *py, double r, const lr_rgba *colours)
{
    cc_canvas *c = as_cairo(base);
    if (!drawable(c) || cairo_status(c->cr) != CAIRO_STATUS_SUCCESS)
        return;
    if (c->vector)
        discs_filled(c, n, px, py, r, colours);
    else if (r < DISC_MIN_ARC_RADIUS ||
        (r <= STAMP_MAX_RADIUS && prepare_stamps(c, r) == 0))
        discs_stamped(c, n, px, py, r, colours);
    else
        discs_filled(c, n, px, py, r, colours);
}

/* text is already valid for cairo (canvas.c cleaned it) */
static void cc_text(lr_canvas *base, double x, double y, double size,
                       lr_rgba colour, lr_align align, const char *clean)
{
    cairo_t *cr = begin(base);
    if (!cr)
        return;
    cairo_set_font_size(cr, size);
    if (align != LR_ALIGN_LEFT) {
        cairo_text_extents_t ext;
        cairo_text_extents(cr, clean, &ext);
        x -= align == LR_ALIGN_CENTER ? ext.x_advance / 2.0 : ext.x_advance;
    }
    set_colour(cr, colour);
    cairo_new_path(cr);
    cairo_move_to(cr, x, y);
    cairo_show_text(cr, clean);
    cairo_restore(cr);
}

/* ---- fills and clips --------------------------------------------------- */

static void cc_fill(lr_canvas *base, size_t npoly, const size_t *counts,
                             const double *xy, lr_rgba colour)
{
    cairo_t *cr = begin(base);
    if (!cr)
        return;
    cairo_set_fill_rule(cr, CAIRO_FILL_RULE_WINDING);
    cairo_new_path(cr);
    const double *p = xy;
    for (size_t k = 0; k < npoly; k++) {
        if (counts[k] >= 3) {
            cairo_move_to(cr, p[0], p[1]);
            for (size_t i = 1; i < counts[k]; i++)
                cairo_line_to(cr, p[2 * i], p[2 * i + 1]);
            cairo_close_path(cr);
        }
        p += 2 * counts[k];
    }
    set_colour(cr, colour);
    cairo_fill(cr);
    cairo_restore(cr);
}

static void cc_clip(lr_canvas *base, int x, int y, int w, int h)
{
    cc_canvas *c = as_cairo(base);
    if (!drawable(c))
        return;
    cairo_reset_clip(c->cr);
    if (w == 0) {
        c->bx0 = c->by0 = 0;
        c->bx1 = c->width;
        c->by1 = c->height;
        return;
    }
    if (w < 0)
        x = y = w = h = 0;      /* nothing */
    cairo_rectangle(c->cr, x, y, w, h);
    cairo_clip(c->cr);
    c->bx0 = x;
    c->by0 = y;
    c->bx1 = x + w;
    c->by1 = y + h;
}

/* ARGB32 is a native-endian uint32 per pixel with premultiplied colour;
 * PNG wants straight RGBA bytes. Rounded division keeps a round trip of
 * opaque colours exact. */
static void unpremultiply_row(const unsigned char *src, unsigned char *dst,
                              int width)
{
    for (int x = 0; x < width; x++) {
        uint32_t p;
        memcpy(&p, src + 4 * (size_t)x, sizeof p);
        uint32_t a = p >> 24;
        uint32_t rgb[3] = { (p >> 16) & 0xFF, (p >> 8) & 0xFF, p & 0xFF };
        unsigned char *d = dst + 4 * (size_t)x;
        for (int k = 0; k < 3; k++) {
            uint32_t v = a ? (rgb[k] * 255 + a / 2) / a : 0;
            d[k] = (unsigned char)(v > 255 ? 255 : v);
        }
        d[3] = (unsigned char)a;
    }
}

static unsigned char *cc_read(lr_canvas *base)
{
    cc_canvas *c = as_cairo(base);
    if (c->vector || !drawable(c) || cairo_status(c->cr) != CAIRO_STATUS_SUCCESS)
        return NULL;
    cairo_surface_flush(c->surface);
    if (cairo_surface_status(c->surface) != CAIRO_STATUS_SUCCESS)
        return NULL;
    const unsigned char *data = cairo_image_surface_get_data(c->surface);
    int stride = cairo_image_surface_get_stride(c->surface);
    if (!data)
        return NULL;
    size_t row = 4 * (size_t)c->width;
    unsigned char *out = malloc(row * (size_t)c->height);
    if (!out)
        return NULL;
    for (int y = 0; y < c->height; y++)
        unpremultiply_row(data + (size_t)y * (size_t)stride, out + (size_t)y * row,
                          c->width);
    return out;
}

static const lr_canvas_ops cairo_ops = {
    .backend = LR_BACKEND_CAIRO,
    .destroy = cc_destroy,
    .clear = cc_clear,
    .line = cc_line,
    .rect = cc_rect,
    .discs = cc_discs,
    .text = cc_text,
    .fill = cc_fill,
    .clip = cc_clip,
    .read_rgba = cc_read,
    .finish = cc_finish,
};
