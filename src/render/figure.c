/* figure.c - laying out and drawing a figure; writing it as PNG, SVG, PDF.
 *
 * Layout: a margin round the image (4 % of its smaller side), a band for
 * the title on top and one for the label below; the rest is divided into
 * rows x cols cells, a margin apart. A cell keeps a band for its panel's
 * title and a strip on the right for its colour bar; the panel's world
 * window is fitted into what is left at one scale for x and y (a circle
 * stays a circle) and centred. For one panel without title or colour bar
 * this is exactly the layout frames always had (frame.c). */
#include "figure_internal.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include "util.h"

const lr_rgba LR_FIG_BACKGROUND = { 1.0, 1.0, 1.0, 1.0 };
const lr_rgba LR_FIG_GRID = { 0.85, 0.85, 0.85, 1.0 };
const lr_rgba LR_FIG_OUTLINE = { 0.35, 0.35, 0.35, 1.0 };
const lr_rgba LR_FIG_TEXT = { 0.2, 0.2, 0.2, 1.0 };

#define MARGIN 0.04         /* of the image's smaller side */
#define TEXT_BAND 1.5       /* height of a text line, in font sizes */

static int has_text(const char *s) { return s && *s; }

/* ---- checks ------------------------------------------------------------- */

static const char *layers_problem(const lr_layers *l)
{
    const lr_grid *g = l->grid;
    if (g && (g->nx < 0 || g->ny < 0 || !(g->hx > 0) || !(g->hy > 0) ||
              !isfinite(g->x0 + g->nx * g->hx) || !isfinite(g->y0 + g->ny * g->hy)))
        return "grid needs finite cell sizes > 0 and cell counts >= 0";
    if ((l->npoints && !l->points) || (l->ncurves && !l->curves) ||
        (l->narrows && !l->arrows) || (l->nfields && !l->fields))
        return "a layer list is missing";
    for (size_t i = 0; i < l->npoints; i++) {
        const lr_points *p = &l->points[i];
        if (p->n > 0 && (!p->x || !p->y))
            return "particle positions missing";
        if (!isfinite(p->radius) || p->radius < 0)
            return "particle radius must be finite and not negative";
        if (!(p->band >= 0) || !isfinite(p->band))
            return "a band's width must be finite and not negative";
    }
    for (size_t i = 0; i < l->ncurves; i++)
        if (l->curves[i].n > 0 && (!l->curves[i].x || !l->curves[i].y))
            return "curve points missing";
    for (size_t i = 0; i < l->narrows; i++) {
        const lr_arrows *a = &l->arrows[i];
        if (a->n > 0 && (!a->x || !a->y || !a->ux || !a->uy))
            return "arrow positions or directions missing";
        if (!(a->thin >= 0) || !isfinite(a->thin) || !(a->spacing >= 0) ||
            !isfinite(a->spacing))
            return "arrows' thinning and spacing must be finite and not negative";
    }
    for (size_t i = 0; i < l->nfields; i++) {
        const lr_field *f = &l->fields[i];
        if (!f->f || f->nx < 1 || f->ny < 1 || (f->nlevels > 0 && !f->levels) ||
            !(f->x1 > f->x0) || !(f->y1 > f->y0))
            return "a filled contour needs samples, nx, ny >= 1, levels and a box";
    }
    return NULL;
}

/* NULL if the figure can be drawn, else what is wrong with it. */
static const char *figure_problem(const lr_figure *f)
{
    if (f->width <= 0 || f->height <= 0)
        return "image size must be positive";
    if (f->npanels == 0 || !f->panels)
        return "a figure needs at least one panel";
    if (f->rows < 0 || f->cols < 0 ||
        (f->rows > 0 && f->cols > 0 && (size_t)f->rows * (size_t)f->cols < f->npanels))
        return "the layout has fewer cells than panels";
    for (size_t k = 0; k < f->npanels; k++) {
        const lr_panel *p = &f->panels[k];
        double ww = p->wx1 - p->wx0, wh = p->wy1 - p->wy0;
        if (!isfinite(ww) || !isfinite(wh) || !(ww > 0) || !(wh > 0))
            return "world window must be finite with wx1 > wx0 and wy1 > wy0";
        if (p->split && !isfinite(p->split_x))
            return "the split position must be finite";
        if ((p->mirror_x && !isfinite(p->mirror_ax)) ||
            (p->mirror_y && !isfinite(p->mirror_ay)))
            return "mirror axes must be finite";
        for (int s = 0; s < (p->split ? 2 : 1); s++) {
            const char *why = layers_problem(&p->side[s]);
            if (why)
                return why;
        }
    }
    return NULL;
}

void lr_panel_mirror_window(const lr_panel *p, double w[4])
{
    if (p->mirror_x) {
        double a = 2.0 * p->mirror_ax - w[2], b = 2.0 * p->mirror_ax - w[0];
        w[0] = fmin(w[0], a);
        w[2] = fmax(w[2], b);
    }
    if (p->mirror_y) {
        double a = 2.0 * p->mirror_ay - w[3], b = 2.0 * p->mirror_ay - w[1];
        w[1] = fmin(w[1], a);
        w[3] = fmax(w[3], b);
    }
}

/* ---- layout ------------------------------------------------------------- */

typedef struct panel_box {
    fig_view v;
    double x, y, w, h;          /* the cell */
    double aw;                  /* its width without the colour bar strip */
    double vmin, vmax;          /* the value range in use */
} panel_box;

typedef struct layout {
    double margin, font;
    int title, label;           /* bands kept for them */
    panel_box *box;
} layout;

/* The value range: the panel's, else the data's (symmetric about zero for
 * a diverging map), else [0, 1]; never empty. */
static void value_range(const lr_panel *p, double *lo, double *hi)
{
    if (p->vmax > p->vmin && isfinite(p->vmin) && isfinite(p->vmax)) {
        *lo = p->vmin;
        *hi = p->vmax;
        return;
    }
    double a = 0, b = 1;
    if (fig_value_range(p, &a, &b) && p->cmap == LR_CMAP_RDBU) {
        b = fmax(fabs(a), fabs(b));
        a = -b;
    }
    if (!(b > a)) {
        double d = a != 0 ? 0.5 * fabs(a) : 1.0;
        a -= d;
        b += d;
    }
    *lo = a;
    *hi = b;
}

void lr_panel_value_range(const lr_panel *p, double *lo, double *hi)
{
    value_range(p, lo, hi);
}

static void grid_shape(const lr_figure *f, int *rows, int *cols)
{
    int n = (int)f->npanels;
    *rows = f->rows;
    *cols = f->cols;
    if (*rows <= 0 && *cols <= 0) {
        *rows = 1;
        *cols = n;
    } else if (*rows <= 0) {
        *rows = (n + *cols - 1) / *cols;
    } else if (*cols <= 0) {
        *cols = (n + *rows - 1) / *rows;
    }
}

/* Fits every panel; -1 if one gets no room. */
static int fit(const lr_figure *f, layout *L)
{
    double w = f->width, h = f->height;
    L->margin = MARGIN * fmin(w, h);
    L->font = fmax(12.0, h / 40.0);
    double band = TEXT_BAND * L->font;
    double top_band = has_text(f->title) ? band : 0.0;
    double bottom_band = has_text(f->label) ? band : 0.0;
    /* In a tiny image the text would crowd out the picture: then the text
     * is drawn over the picture instead of beside it. */
    if (h - 2.0 * L->margin - top_band - bottom_band < 0.5 * h)
        top_band = bottom_band = 0.0;
    double left = L->margin, right = w - L->margin;
    double top = L->margin + top_band, bottom = h - L->margin - bottom_band;
    int rows, cols;
    grid_shape(f, &rows, &cols);
    double gap = L->margin;
    double cw = (right - left - (cols - 1) * gap) / cols;
    double ch = (bottom - top - (rows - 1) * gap) / rows;
    for (size_t k = 0; k < f->npanels; k++) {
        const lr_panel *p = &f->panels[k];
        panel_box *b = &L->box[k];
        int r = (int)k / cols, col = (int)k % cols;
        b->x = left + col * (cw + gap);
        b->y = top + r * (ch + gap);
        b->w = cw;
        b->h = ch;
        value_range(p, &b->vmin, &b->vmax);
        double title_band = has_text(p->title) ? band : 0.0;
        double strip = p->colourbar ? fig_colourbar_width(p, L->font, b->vmin, b->vmax) : 0.0;
        double aw = cw - strip, ah = ch - title_band;
        b->aw = aw;
        if (aw < 1.0 || ah < 1.0)
            return -1;
        double pleft = b->x, ptop = b->y + title_band;
        double ww = p->wx1 - p->wx0, wh = p->wy1 - p->wy0;
        fig_view *v = &b->v;
        v->s = fmin(aw / ww, ah / wh);
        if (!(v->s > 0) || !isfinite(v->s))
            return -1;
        v->ox = pleft + 0.5 * (aw - v->s * ww) - v->s * p->wx0;
        v->oy = ptop + 0.5 * (ah - v->s * wh) + v->s * p->wy1;
        v->wx0 = p->wx0;
        v->wy0 = p->wy0;
        v->wx1 = p->wx1;
        v->wy1 = p->wy1;
    }
    L->title = top_band > 0;
    L->label = bottom_band > 0;
    return 0;
}

/* ---- drawing ------------------------------------------------------------ */

/* The mirror copies of a panel: itself, then its reflections. */
static int mirror_copies(const lr_panel *p, fig_mirror m[4])
{
    int n = 0;
    for (int fy = 0; fy <= (p->mirror_y ? 1 : 0); fy++)
        for (int fx = 0; fx <= (p->mirror_x ? 1 : 0); fx++) {
            m[n].fx = fx;
            m[n].fy = fy;
            m[n].ax = p->mirror_ax;
            m[n].ay = p->mirror_ay;
            n++;
        }
    return n;
}

/* A grid copy: the reflected grid is a grid again; the sides lying on an
 * axis are not walls. */
/* One mirrored axis of a grid copy, lo..hi along it, the mirror at ax:
 * the copy's origin when flipped, and the walls (skip_lo, skip_hi before
 * the flip) that lie on the mirror. */
static void mirror_axis(double ax, double lo, double hi, int flip, int skip_lo,
                        int skip_hi, double *origin, int *skip)
{
    double t = 1e-9 * (hi - lo);
    if (flip)
        *origin = 2.0 * ax - hi;
    if (fabs(ax - lo) <= t)
        *skip |= flip ? skip_hi : skip_lo;
    if (fabs(ax - hi) <= t)
        *skip |= flip ? skip_lo : skip_hi;
}

static void draw_grid_copy(lr_canvas *c, const fig_view *v, const lr_grid *g,
                           const lr_panel *p, const fig_mirror *m)
{
    lr_grid r = *g;
    int skip = 0;
    if (p->mirror_x)
        mirror_axis(p->mirror_ax, g->x0, g->x0 + g->nx * g->hx, m->fx, FIG_SKIP_LEFT,
                    FIG_SKIP_RIGHT, &r.x0, &skip);
    if (p->mirror_y)
        mirror_axis(p->mirror_ay, g->y0, g->y0 + g->ny * g->hy, m->fy, FIG_SKIP_BOTTOM,
                    FIG_SKIP_TOP, &r.y0, &skip);
    fig_draw_grid(c, v, &r, skip);
}

/* A clip rectangle in whole pixels; w < 0: none. */
typedef struct clip_rect {
    int x, y, w, h;
} clip_rect;

static void set_clip(lr_canvas *c, clip_rect r)
{
    if (r.w < 0)
        lr_canvas_unclip(c);
    else
        lr_canvas_clip(c, r.x, r.y, r.w, r.h);
}

/* The overlays' clip: the panel's window in pixels (rounded outward, so a
 * line on the window's edge keeps its width), within the side's own clip.
 * Curves and arrows end at the window (issue 32: arrows and phi lines
 * outside a close-up ran over the title and the next panel); discs
 * partly inside it are still drawn whole, as before. */
static clip_rect window_clip(const panel_box *b, const lr_panel *p, clip_rect side)
{
    double x0, y0, x1, y1;
    fig_to_pixel(&b->v, p->wx0, p->wy1, &x0, &y0);
    fig_to_pixel(&b->v, p->wx1, p->wy0, &x1, &y1);
    int ix0 = (int)floor(x0), iy0 = (int)floor(y0);
    int ix1 = (int)ceil(x1), iy1 = (int)ceil(y1);
    if (side.w >= 0) {
        ix0 = ix0 > side.x ? ix0 : side.x;
        iy0 = iy0 > side.y ? iy0 : side.y;
        ix1 = ix1 < side.x + side.w ? ix1 : side.x + side.w;
        iy1 = iy1 < side.y + side.h ? iy1 : side.y + side.h;
    }
    clip_rect r = { ix0, iy0, ix1 > ix0 ? ix1 - ix0 : 0, iy1 > iy0 ? iy1 - iy0 : 0 };
    return r;
}

/* One side's layers, each over all mirror copies before the next layer,
 * so a copy's grid never covers another copy's particles; the curves and
 * arrows clipped to the window (window_clip), the side's clip restored
 * after them. */
static int draw_side(lr_canvas *c, const panel_box *b, const lr_panel *p,
                     const lr_layers *l, clip_rect side)
{
    fig_mirror m[4];
    int nm = mirror_copies(p, m), rc = 0;
    if (l->grid)
        for (int k = 0; k < nm; k++)
            draw_grid_copy(c, &b->v, l->grid, p, &m[k]);
    for (size_t i = 0; i < l->nfields && rc == 0; i++)
        for (int k = 0; k < nm && rc == 0; k++)
            rc = fig_draw_field(c, &b->v, &m[k], &l->fields[i], p, b->vmin, b->vmax);
    for (size_t i = 0; i < l->npoints && rc == 0; i++)
        for (int k = 0; k < nm && rc == 0; k++)
            rc = fig_draw_points(c, &b->v, &m[k], &l->points[i], p, b->vmin, b->vmax);
    if (rc != 0 || (l->ncurves == 0 && l->narrows == 0))
        return rc;
    set_clip(c, window_clip(b, p, side));
    for (size_t i = 0; i < l->ncurves; i++)
        for (int k = 0; k < nm; k++)
            fig_draw_curve(c, &b->v, &m[k], &l->curves[i]);
    for (size_t i = 0; i < l->narrows && rc == 0; i++)
        for (int k = 0; k < nm && rc == 0; k++)
            rc = fig_draw_arrows(c, &b->v, &m[k], &l->arrows[i]);
    set_clip(c, side);
    return rc;
}

/* Text on a pale box, readable over particles. */
static void boxed_text(lr_canvas *c, double x, double y, double size,
                       lr_align align, const char *text)
{
    if (!has_text(text))
        return;
    double w = lr_text_width(size, text);
    double x0 = align == LR_ALIGN_LEFT ? x : align == LR_ALIGN_CENTER ? x - 0.5 * w : x - w;
    double pad = 0.25 * size;
    double box[8] = { x0 - pad, y - size - pad * 0.2, x0 + w + pad, y - size - pad * 0.2,
                      x0 + w + pad, y + 0.3 * size + pad, x0 - pad, y + 0.3 * size + pad };
    size_t four = 4;
    const lr_rgba backing = { 1, 1, 1, 0.75 };
    lr_canvas_fill(c, 1, &four, box, backing);
    lr_canvas_text(c, x, y, size, LR_FIG_TEXT, align, text);
}

static int uses_values(const lr_panel *p)
{
    for (int s = 0; s < (p->split ? 2 : 1); s++) {
        for (size_t i = 0; i < p->side[s].npoints; i++)
            if (p->side[s].points[i].value)
                return 1;
        for (size_t i = 0; i < p->side[s].nfields; i++)
            if (!p->side[s].fields[i].colours)
                return 1;
    }
    return 0;
}

/* A diverging map is white at its middle: on a white page values near zero
 * would vanish, so the window gets a pale grey ground. */
static void ground(lr_canvas *c, const panel_box *b, const lr_panel *p)
{
    if (p->cmap != LR_CMAP_RDBU || !uses_values(p))
        return;
    double x0, y0, x1, y1;
    fig_to_pixel(&b->v, p->wx0, p->wy1, &x0, &y0);
    fig_to_pixel(&b->v, p->wx1, p->wy0, &x1, &y1);
    x0 = floor(x0 + 0.5);
    y0 = floor(y0 + 0.5);
    x1 = floor(x1 + 0.5);
    y1 = floor(y1 + 0.5);
    double box[8] = { x0, y0, x1, y0, x1, y1, x0, y1 };
    size_t four = 4;
    const lr_rgba pale = { 0.9, 0.9, 0.9, 1.0 };
    lr_canvas_fill(c, 1, &four, box, pale);
}

static int draw_panel(lr_canvas *c, const lr_figure *f, const layout *L, size_t k)
{
    const lr_panel *p = &f->panels[k];
    const panel_box *b = &L->box[k];
    int clipped = f->npanels > 1 || p->split, rc = 0;
    /* the cell without the colour bar strip, in whole pixels */
    int cx0 = (int)floor(b->x), cy0 = (int)floor(b->y);
    int cx1 = (int)ceil(b->x + b->aw), cy1 = (int)ceil(b->y + b->h);
    double top, bottom, px, unused;
    fig_to_pixel(&b->v, p->wx0, p->wy1, &unused, &top);
    fig_to_pixel(&b->v, p->wx0, p->wy0, &unused, &bottom);
    int split_px = 0;
    if (p->split) {
        fig_to_pixel(&b->v, p->split_x, 0, &px, &unused);
        split_px = (int)lround(px);
        split_px = split_px < cx0 ? cx0 : split_px > cx1 ? cx1 : split_px;
    }
    ground(c, b, p);
    for (int s = 0; s < (p->split ? 2 : 1) && rc == 0; s++) {
        clip_rect side = { 0, 0, -1, -1 };
        if (clipped) {
            int x0 = p->split && s == 1 ? split_px : cx0;
            int x1 = p->split && s == 0 ? split_px : cx1;
            side = (clip_rect){ x0, cy0, x1 - x0, cy1 - cy0 };
            set_clip(c, side);
        }
        rc = draw_side(c, b, p, &p->side[s], side);
    }
    if (clipped)
        lr_canvas_unclip(c);
    if (p->split) {
        lr_canvas_line(c, split_px, floor(top), split_px, ceil(bottom), 2.0,
                       LR_FIG_TEXT, 0.0);
        double size = 0.8 * L->font, y = top + 1.5 * size;
        boxed_text(c, split_px - 0.5 * size, y, size, LR_ALIGN_RIGHT, p->side[0].name);
        boxed_text(c, split_px + 0.5 * size, y, size, LR_ALIGN_LEFT, p->side[1].name);
    }
    if (p->scalebar != 0)
        fig_draw_scalebar(c, &b->v, p, L->font);
    if (p->colourbar) {     /* beside the window, which is centred with it */
        double right;
        fig_to_pixel(&b->v, p->wx1, p->wy0, &right, &unused);
        fig_draw_colourbar(c, p, right, top, bottom, L->font, b->vmin, b->vmax);
    }
    if (has_text(p->title))
        lr_canvas_text(c, b->x + 0.5 * b->aw, b->y + L->font, L->font, LR_FIG_TEXT,
                       LR_ALIGN_CENTER, p->title);
    return rc;
}

/* 0, or -1 with what is wrong with the figure (or that there is none) in
 * err: drawing and rendering refuse alike. */
static int figure_ok(const lr_figure *f, char *err, size_t errlen)
{
    return fig_refuse("", f ? figure_problem(f) : "no figure", err, errlen);
}

int fig_refuse(const char *what, const char *problem, char *err, size_t errlen)
{
    if (problem)
        lu_err(err, errlen, "%s%s", what, problem);
    return problem ? -1 : 0;
}

int fig_canvas_fits(const char *what, const lr_canvas *c, int w, int h, char *err,
                    size_t errlen)
{
    if (c && lr_canvas_width(c) == w && lr_canvas_height(c) == h)
        return 0;
    lu_err(err, errlen, "%sthe canvas is not the figure's size", what);
    return -1;
}

int lr_figure_draw(const lr_figure *f, lr_canvas *c, char *err, size_t errlen)
{
    if (figure_ok(f, err, errlen) != 0 ||
        fig_canvas_fits("", c, f->width, f->height, err, errlen) != 0)
        return -1;
    layout L;
    L.box = calloc(f->npanels, sizeof *L.box);
    if (!L.box) {
        lu_err(err, errlen, "out of memory");
        return -1;
    }
    if (fit(f, &L) != 0) {
        lu_err(err, errlen, "image %dx%d is too small for the frame", f->width,
                f->height);
        free(L.box);
        return -1;
    }
    lr_canvas_clear(c, LR_FIG_BACKGROUND);
    int rc = 0;
    for (size_t k = 0; k < f->npanels && rc == 0; k++)
        rc = draw_panel(c, f, &L, k);
    /* label bottom-left, title centred on top, each in its reserved band */
    if (has_text(f->label))
        lr_canvas_text(c, L.margin, f->height - L.margin - 0.3 * L.font, L.font,
                       LR_FIG_TEXT, LR_ALIGN_LEFT, f->label);
    if (has_text(f->title))
        lr_canvas_text(c, 0.5 * f->width, L.margin + L.font, L.font, LR_FIG_TEXT,
                       LR_ALIGN_CENTER, f->title);
    free(L.box);
    if (rc != 0)
        lu_err(err, errlen, "drawing failed (out of memory)");
    return rc;
}

/* ---- output ------------------------------------------------------------- */

unsigned char *fig_render(lr_backend b, int w, int h, fig_draw_fn draw, const void *ctx,
                          char *err, size_t errlen)
{
    char why[256] = "";
    lr_canvas *c = lr_canvas_new(b, w, h, why, sizeof why);
    if (!c) {
        lu_err(err, errlen, "%s", why);
        return NULL;
    }
    unsigned char *rgba = NULL;
    if (draw(ctx, c, err, errlen) == 0) {
        rgba = lr_canvas_read_rgba(c);
        if (!rgba)
            lu_err(err, errlen, "drawing failed (out of memory)");
    }
    lr_canvas_free(c);
    return rgba;
}

static int draw_figure(const void *f, lr_canvas *c, char *err, size_t errlen)
{
    return lr_figure_draw(f, c, err, errlen);
}

unsigned char *lr_figure_render(const lr_figure *f, char *err, size_t errlen)
{
    if (figure_ok(f, err, errlen) != 0)
        return NULL;
    return fig_render(f->backend, f->width, f->height, draw_figure, f, err, errlen);
}

static int write_vector(const lr_figure *f, const char *path, lr_format fmt,
                        char *err, size_t errlen)
{
    if (f->backend != LR_BACKEND_CAIRO) {
        lu_err(err, errlen, "cannot write '%s': %s output is drawn by cairo, "
                "not by the %s backend (use backend = \"cairo\" or a .png name)",
                path, fmt == LR_FORMAT_SVG ? "SVG" : "PDF", lr_backend_name(f->backend));
        return -1;
    }
    char why[512] = "";
    const char *problem = figure_problem(f);
    if (problem) {
        lu_err(err, errlen, "cannot write '%s': %s", path, problem);
        return -1;
    }
    lr_canvas *c = lr_canvas_vector_new(path, fmt, f->width, f->height, f->text,
                                        f->ntext, err, errlen);
    if (!c)
        return -1;
    if (lr_figure_draw(f, c, why, sizeof why) != 0) {
        lr_canvas_free(c);      /* removes the temporary */
        lu_err(err, errlen, "cannot write '%s': %s", path, why);
        return -1;
    }
    int rc = lr_canvas_finish(c, err, errlen);
    lr_canvas_free(c);
    return rc;
}

int lr_figure_write(const lr_figure *f, const char *path, char *err, size_t errlen)
{
    if (!f || !path || !*path) {
        lu_err(err, errlen, "cannot write frame: %s", f ? "empty path" : "no frame");
        return -1;
    }
    lr_format fmt = lr_format_of(path);
    if (fmt != LR_FORMAT_PNG)
        return write_vector(f, path, fmt, err, errlen);
    char why[512] = "";
    unsigned char *rgba = lr_figure_render(f, why, sizeof why);
    if (!rgba) {
        lu_err(err, errlen, "cannot write '%s': %s", path, why);
        return -1;
    }
    int rc = lr_image_write(path, f->width, f->height, rgba, f->text, f->ntext,
                            err, errlen);
    free(rgba);
    return rc;
}
