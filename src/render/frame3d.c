/* frame3d.c - a 3D run's frame (frame3d.h): the camera, the layout of
 * panels (the figure's: a margin of 4 % of the smaller side, a band for
 * the title on top and one for the label below, rows x cols cells a
 * margin apart, each with a band for its title and strips on the right
 * for its colour bars), and each panel's layers gathered into a view3d.h
 * scene and drawn through the canvas's backend. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "figure_internal.h"
#include "frame3d.h"
#include "util.h"
#include "view3d.h"

#define MARGIN 0.04         /* of the image's smaller side (figure.c) */
#define TEXT_BAND 1.5       /* a text line, in font sizes (figure.c) */
#define DEG 0.017453292519943295769
#define REF_FOV 30.0        /* an orthographic camera's distance reads as this fov's */
#define MAX_BARS 4          /* colour bars a panel shows: its own and its slices' */

static int has_text(const char *s) { return s && *s; }

void lr_camera3d_view(lr_view *v, const lr_camera3d *cam, double px, double py, double pw,
                      double ph, const double lo[3], const double hi[3])
{
    lr_view_3d(v, px, py, pw, ph, lo, hi, cam->azimuth, cam->elevation);
    if (cam->has_target)
        memcpy(v->c, cam->target, sizeof v->c);
    double fov = cam->fov > 0 ? cam->fov : REF_FOV;
    double half = 0.5 * fmin(pw, ph);
    if (cam->distance > 0)
        v->s = half / (cam->distance * tan(0.5 * fov * DEG));
    if (cam->fov > 0 && cam->distance > 0) {
        v->persp = cam->distance;
    } else if (cam->fov > 0) {
        /* the box fitted at its nearest corner's depth r, not at the
         * target's: the eye D + r from the target, D where the fitted
         * picture spans the fov, the scale at the target D / (D + r) of
         * the fit's (so the near corners stay about inside) */
        double r = 0;
        for (int k = 0; k < 8; k++) {
            double d = 0;
            for (int a = 0; a < 3; a++)
                d += (((k >> a) & 1 ? hi[a] : lo[a]) - v->c[a]) * v->toward[a];
            r = fmax(r, d);
        }
        double D = half / v->s / tan(0.5 * fov * DEG);
        v->s *= D / (D + r);
        v->persp = D + r;
    }
}

/* ---- values and colours -------------------------------------------------- */

static void widen(const double *f, size_t n, double *a, double *b, int *found)
{
    double lo = *a, hi = *b;
    for (size_t i = 0; f && i < n; i++)
        if (isfinite(f[i])) {
            lo = f[i] < lo ? f[i] : lo;
            hi = f[i] > hi ? f[i] : hi;
            *found = 1;
        }
    *a = lo;
    *b = hi;
}

static void settle(lr_cmap m, int found, double *a, double *b)
{
    if (!found) {
        *a = 0;
        *b = 1;
    } else if (m == LR_CMAP_RDBU) {
        *b = fmax(fabs(*a), fabs(*b));
        *a = -*b;
    }
    if (!(*b > *a)) {
        double d = *a != 0 ? 0.5 * fabs(*a) : 1.0;
        *a -= d;
        *b += d;
    }
}

void lr_panel3d_range(const lr_panel3d *p, double *lo, double *hi)
{
    if (p->vmax > p->vmin && isfinite(p->vmin) && isfinite(p->vmax)) {
        *lo = p->vmin;
        *hi = p->vmax;
        return;
    }
    double a = INFINITY, b = -INFINITY;
    int found = 0;
    for (size_t k = 0; k < p->nclouds; k++)
        widen(p->clouds[k].value, p->clouds[k].n, &a, &b, &found);
    for (size_t k = 0; k < p->nmembranes; k++)
        widen(p->membranes[k].value, p->membranes[k].n, &a, &b, &found);
    settle(p->cmap, found, &a, &b);
    *lo = a;
    *hi = b;
}

static size_t grid_count(const lr_grid3d *g)
{
    return (size_t)g->n[0] * (size_t)g->n[1] * (size_t)g->n[2];
}

static void slice_range(const lr_slice3d *s, double *lo, double *hi)
{
    if (s->vmax > s->vmin && isfinite(s->vmin) && isfinite(s->vmax)) {
        *lo = s->vmin;
        *hi = s->vmax;
        return;
    }
    double a = INFINITY, b = -INFINITY;
    int found = 0;
    widen(s->grid.f, grid_count(&s->grid), &a, &b, &found);
    settle(s->cmap, found, &a, &b);
    *lo = a;
    *hi = b;
}

static lr_rgba value_colour(lr_cmap m, double v, double lo, double hi)
{
    return lr_cmap_colour(m, (v - lo) / (hi - lo));
}

/* ---- checks ---------------------------------------------------------------- */

static int grid_ok(const lr_grid3d *g)
{
    if (!g->f)
        return 0;
    for (int a = 0; a < 3; a++)
        if (g->n[a] < 2 || !(g->h[a] > 0) || !isfinite(g->lo[a]) || !isfinite(g->h[a]))
            return 0;
    return 1;
}

static const char *panel_problem(const lr_panel3d *p)
{
    for (int a = 0; a < 3; a++)
        if (!(p->hi[a] > p->lo[a]) || !isfinite(p->lo[a]) || !isfinite(p->hi[a]))
            return "a panel's box is empty or not finite";
    const lr_camera3d *c = &p->camera;
    if (!isfinite(c->azimuth) || !isfinite(c->elevation) || !(c->distance >= 0) ||
        !isfinite(c->distance) || !(c->fov >= 0 && c->fov < 120))
        return "a panel's camera is not finite (or fov outside [0, 120))";
    for (size_t k = 0; k < p->nclouds; k++)
        if ((p->clouds[k].n && (!p->clouds[k].x || !p->clouds[k].y || !p->clouds[k].z)) ||
            !(p->clouds[k].radius > 0))
            return "a cloud without positions or radius";
    for (size_t k = 0; k < p->nmembranes; k++)
        if ((p->membranes[k].n &&
             (!p->membranes[k].x || !p->membranes[k].y || !p->membranes[k].z)) ||
            !(p->membranes[k].radius > 0))
            return "a membrane without positions or radius";
    for (size_t k = 0; k < p->nisos; k++)
        if (!grid_ok(&p->isos[k].grid))
            return "an isosurface's grid needs values, >= 2 nodes and a spacing > 0 each way";
    for (size_t k = 0; k < p->ntris; k++)
        if (p->tris[k].n && !p->tris[k].xyz)
            return "triangles without corners";
    for (size_t k = 0; k < p->nslices; k++) {
        const lr_slice3d *s = &p->slices[k];
        if (!grid_ok(&s->grid) || s->axis < 0 || s->axis > 2)
            return "a slice's grid needs values, >= 2 nodes and a spacing > 0 each way, "
                   "and an axis 0, 1 or 2";
        double lo = s->grid.lo[s->axis], hi = lo + (s->grid.n[s->axis] - 1) * s->grid.h[s->axis];
        if (!(s->at >= lo && s->at <= hi))
            return "a slice's plane is outside its grid";
    }
    return NULL;
}

static const char *figure_problem(const lr_figure3d *f)
{
    if (f->width < 16 || f->height < 16 || f->width > 16384 || f->height > 16384)
        return "width and height must be in [16, 16384]";
    if (!f->panels || f->npanels < 1)
        return "a 3D frame needs at least one panel";
    for (size_t k = 0; k < f->npanels; k++) {
        const char *why = panel_problem(&f->panels[k]);
        if (why)
            return why;
    }
    return NULL;
}

/* ---- layers into the scene ------------------------------------------------- */

/* Values to packed colours through a table of the map at LUT_N + 1
 * evenly spaced points (nearest), so that 10^6 particles cost a lookup
 * each: within 1 / (2 LUT_N) of t, under one level of 255 of the map's
 * colour. NaN gives the map's NaN colour. */
#define LUT_N 1024

typedef struct cmap_lut {
    uint32_t c[LUT_N + 1], nan;
    double lo, scale;
} cmap_lut;

static void lut_make(cmap_lut *t, lr_cmap m, double lo, double hi)
{
    for (int i = 0; i <= LUT_N; i++)
        t->c[i] = lr_rgba_pack(lr_cmap_colour(m, (double)i / LUT_N));
    t->nan = lr_rgba_pack(lr_cmap_colour(m, NAN));
    t->lo = lo;
    t->scale = LUT_N / (hi - lo);
}

static uint32_t lut_at(const cmap_lut *t, double v)
{
    double u = (v - t->lo) * t->scale;
    if (u != u)
        return t->nan;
    u = u < 0 ? 0 : u > LUT_N ? LUT_N : u;
    return t->c[(int)(u + 0.5)];
}

static int add_points(lr_scene3d *s, size_t n, const double *const q[3], const double *value,
                      const int *group, const uint32_t *one, const cmap_lut *lut,
                      double radius)
{
    if (n == 0)
        return 0;
    uint32_t *col = malloc(n * sizeof *col);
    if (!col)
        return -1;
    for (size_t i = 0; i < n; i++)
        col[i] = value ? lut_at(lut, value[i])
                 : one ? *one : lr_rgba_pack(lr_palette(group ? group[i] : 0));
    int rc = lr_scene3d_cloud_rgba8(s, n, q, col, radius);
    free(col);
    return rc;
}

static int add_cloud(lr_scene3d *s, const lr_cloud3d *c, const cmap_lut *lut)
{
    const double *const q[3] = {c->x, c->y, c->z};
    return add_points(s, c->n, q, c->value, c->group, NULL, lut, c->radius);
}

/* The points to draw normals at: per cube of side L (a grid from the
 * origin), the point nearest the cube's centre, ties to the lower index;
 * in the order the cubes are first met, so the same points give the same
 * picks. An open-addressing table of the cubes (twice the points). NULL
 * when memory ran out. */
static size_t *thin_by_cubes(const lr_membrane3d *m, double L, size_t *count)
{
    size_t cap = 16;
    while (cap < 2 * m->n) cap *= 2;
    int64_t *key = malloc(cap * 3 * sizeof *key);
    size_t *best = malloc(cap * sizeof *best);
    size_t *order = malloc((m->n + 1) * sizeof *order);
    if (!key || !best || !order) {
        free(key);
        free(best);
        free(order);
        return NULL;
    }
    for (size_t k = 0; k < cap; k++) best[k] = SIZE_MAX;
    size_t used = 0;
    for (size_t i = 0; i < m->n; i++) {
        const double x[3] = {m->x[i], m->y[i], m->z[i]};
        int64_t c[3];
        double d2 = 0;
        for (int a = 0; a < 3; a++) {
            c[a] = (int64_t)floor(x[a] / L);
            double o = x[a] - (c[a] + 0.5) * L;
            d2 += o * o;
        }
        uint64_t h = ((uint64_t)c[0] * 73856093u) ^ ((uint64_t)c[1] * 19349663u) ^
                     ((uint64_t)c[2] * 83492791u);
        size_t k = (size_t)(h & (cap - 1));
        while (best[k] != SIZE_MAX &&
               (key[3 * k] != c[0] || key[3 * k + 1] != c[1] || key[3 * k + 2] != c[2]))
            k = (k + 1) & (cap - 1);
        if (best[k] == SIZE_MAX) {
            key[3 * k] = c[0];
            key[3 * k + 1] = c[1];
            key[3 * k + 2] = c[2];
            best[k] = i;
            order[used++] = k;
            continue;
        }
        size_t b = best[k];
        double e2 = 0;
        const double y[3] = {m->x[b], m->y[b], m->z[b]};
        for (int a = 0; a < 3; a++) {
            double o = y[a] - (c[a] + 0.5) * L;
            e2 += o * o;
        }
        if (d2 < e2) best[k] = i;
    }
    for (size_t j = 0; j < used; j++) order[j] = best[order[j]];
    free(key);
    free(best);
    *count = used;
    return order;
}

/* A membrane: its points, then its normals thinned to the spacing (one a
 * cube of k spacings, k the least with k spacings >= arrow_px pixels, each
 * arrow that long - the 2D frames' rule, l_frame_points.c, on a surface). */
static int add_membrane(lr_scene3d *s, const lr_view *v, const lr_membrane3d *m,
                        const cmap_lut *lut)
{
    if (m->n == 0)
        return 0;
    const double *const q[3] = {m->x, m->y, m->z};
    uint32_t one = lr_rgba_pack(m->colour);
    int rc = add_points(s, m->n, q, m->value, NULL, &one, lut, m->radius);
    if (rc != 0 || !m->nx || !m->ny || !m->nz)
        return rc;
    double gap = m->arrow_px > 0 ? m->arrow_px : 16.0;
    double sp = m->spacing > 0 ? m->spacing : 0;
    size_t every = 1;
    if (sp > 0) {
        double k = ceil(gap / (sp * v->s));
        every = k > 1 ? (size_t)fmin(k, 65536) : 1;     /* squared below */
    }
    double length = sp > 0 ? every * sp : gap / v->s;
    /* in 3D the points are not in a line: one arrow per cube of side
     * `length` (the point nearest the cube's centre), so the arrows are
     * about k spacings apart over the surface whatever order the sampler
     * gave the points (every k^2-th in order drew stripes along a
     * Fibonacci sphere's spiral) */
    size_t n = 0;
    size_t *pick = thin_by_cubes(m, length, &n);
    if (!pick)
        return -1;
    double *buf = malloc(6 * (n + 1) * sizeof *buf);
    if (!buf) {
        free(pick);
        return -1;
    }
    for (size_t j = 0; j < n; j++) {
        size_t i = pick[j];
        buf[j] = m->x[i];
        buf[n + j] = m->y[i];
        buf[2 * n + j] = m->z[i];
        buf[3 * n + j] = m->nx[i];
        buf[4 * n + j] = m->ny[i];
        buf[5 * n + j] = m->nz[i];
    }
    free(pick);
    const double *const pa[3] = {buf, buf + n, buf + 2 * n};
    const double *const da[3] = {buf + 3 * n, buf + 4 * n, buf + 5 * n};
    rc = lr_scene3d_arrows(s, n, pa, da, length, 1.5, 7.0, m->arrow_colour, 0.0);
    free(buf);
    return rc;
}

static int add_iso(lr_scene3d *s, const lr_iso3d *iso)
{
    double *xyz = NULL, *nrm = NULL;
    size_t n = 0;
    if (lr_iso_triangles(&iso->grid, iso->level, &xyz, &nrm, &n) != 0)
        return -1;
    int rc = n ? lr_scene3d_triangles(s, n, xyz, nrm, NULL, iso->colour) : 0;
    free(xyz);
    free(nrm);
    return rc;
}

/* The value of g at the plane axis = at, node (i, j) of the plane's two
 * other axes (linear between the node planes). */
static double plane_value(const lr_grid3d *g, int axis, double at, int i, int j)
{
    int a1 = (axis + 1) % 3, a2 = (axis + 2) % 3;
    double u = (at - g->lo[axis]) / g->h[axis];
    int k = (int)floor(u);
    if (k > g->n[axis] - 2)
        k = g->n[axis] - 2;
    if (k < 0)
        k = 0;
    double t = u - k;
    double f[2];
    for (int m = 0; m < 2; m++) {
        int ijk[3];
        ijk[axis] = k + m;
        ijk[a1] = i;
        ijk[a2] = j;
        f[m] = g->f[((size_t)ijk[2] * (size_t)g->n[1] + (size_t)ijk[1]) * (size_t)g->n[0] +
                    (size_t)ijk[0]];
    }
    if (t == 0)
        return f[0];
    return f[0] + t * (f[1] - f[0]);
}

/* A slice as two triangles a cell, coloured per vertex (cells with a node
 * without a value are left out: the plane shows where the field is). */
static int add_slice(lr_scene3d *s, const lr_slice3d *sl)
{
    const lr_grid3d *g = &sl->grid;
    int a1 = (sl->axis + 1) % 3, a2 = (sl->axis + 2) % 3;
    int n1 = g->n[a1], n2 = g->n[a2];
    double lo, hi;
    slice_range(sl, &lo, &hi);
    size_t cells = (size_t)(n1 - 1) * (size_t)(n2 - 1);
    double *xyz = malloc(18 * cells * sizeof *xyz);
    lr_rgba *col = malloc(6 * cells * sizeof *col);
    double *val = malloc((size_t)n1 * (size_t)n2 * sizeof *val);
    if (!xyz || !col || !val) {
        free(xyz);
        free(col);
        free(val);
        return -1;
    }
    for (int j = 0; j < n2; j++)
        for (int i = 0; i < n1; i++)
            val[(size_t)j * n1 + i] = plane_value(g, sl->axis, sl->at, i, j);
    double alpha = sl->alpha > 0 && sl->alpha < 1 ? sl->alpha : 1.0;
    size_t nt = 0;
    static const int quad[6][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 0}, {1, 1}, {0, 1}};
    for (int j = 0; j + 1 < n2; j++)
        for (int i = 0; i + 1 < n1; i++) {
            int ok = 1;
            for (int c = 0; c < 4; c++)
                ok &= isfinite(val[(size_t)(j + (c >> 1)) * n1 + i + (c & 1)]);
            if (!ok)
                continue;
            for (int v = 0; v < 6; v++) {
                int ii = i + quad[v][0], jj = j + quad[v][1];
                double *q = xyz + 9 * nt + 3 * (v % 3) + (v >= 3 ? 9 : 0);
                q[sl->axis] = sl->at;
                q[a1] = g->lo[a1] + ii * g->h[a1];
                q[a2] = g->lo[a2] + jj * g->h[a2];
                lr_rgba k = value_colour(sl->cmap, val[(size_t)jj * n1 + ii], lo, hi);
                k.a = alpha;
                col[3 * nt + (size_t)v] = k;
            }
            nt += 2;
        }
    int rc = nt ? lr_scene3d_triangles(s, nt, xyz, NULL, col, col[0]) : 0;
    free(xyz);
    free(col);
    free(val);
    return rc;
}

static int fill_scene(lr_scene3d *s, const lr_view *v, const lr_panel3d *p, double lo,
                      double hi)
{
    cmap_lut lut;
    lut_make(&lut, p->cmap, lo, hi);
    static const lr_rgba OUTLINE = {0.35, 0.35, 0.35, 1};
    int rc = 0;
    if (p->box)
        rc |= lr_scene3d_box(s, p->lo, p->hi, 1.2, OUTLINE);
    for (size_t k = 0; k < p->nslices && rc == 0; k++)
        rc |= add_slice(s, &p->slices[k]);
    for (size_t k = 0; k < p->nclouds && rc == 0; k++)
        rc |= add_cloud(s, &p->clouds[k], &lut);
    for (size_t k = 0; k < p->nmembranes && rc == 0; k++)
        rc |= add_membrane(s, v, &p->membranes[k], &lut);
    for (size_t k = 0; k < p->nisos && rc == 0; k++)
        rc |= add_iso(s, &p->isos[k]);
    for (size_t k = 0; k < p->ntris && rc == 0; k++)
        if (p->tris[k].n)
            rc |= lr_scene3d_triangles(s, p->tris[k].n, p->tris[k].xyz, p->tris[k].normals,
                                       NULL, p->tris[k].colour);
    return rc;
}

/* ---- layout and drawing ---------------------------------------------------- */

typedef struct bar {
    lr_panel p;         /* what figure_bars.c reads: cmap, label */
    double lo, hi;
} bar;

/* A panel's colour bars: the particles', then each slice's that has one. */
static int panel_bars(const lr_panel3d *p, bar out[MAX_BARS])
{
    int n = 0;
    if (p->colourbar) {
        memset(&out[n], 0, sizeof out[n]);
        out[n].p.cmap = p->cmap;
        out[n].p.colourbar_label = p->colourbar_label;
        lr_panel3d_range(p, &out[n].lo, &out[n].hi);
        n++;
    }
    for (size_t k = 0; k < p->nslices && n < MAX_BARS; k++) {
        if (!p->slices[k].colourbar)
            continue;
        memset(&out[n], 0, sizeof out[n]);
        out[n].p.cmap = p->slices[k].cmap;
        out[n].p.colourbar_label = p->slices[k].label;
        slice_range(&p->slices[k], &out[n].lo, &out[n].hi);
        n++;
    }
    return n;
}

static int draw_panel(lr_canvas *c, const lr_panel3d *p, double x, double y, double w,
                      double h, double font, char *err, size_t errlen)
{
    bar bars[MAX_BARS];
    int nb = panel_bars(p, bars);
    double strips = 0;
    for (int b = 0; b < nb; b++)
        strips += fig_colourbar_width(&bars[b].p, font, bars[b].lo, bars[b].hi);
    double band = has_text(p->title) ? TEXT_BAND * font : 0.0;
    double aw = w - strips, ah = h - band;
    if (aw < 8 || ah < 8) {
        lu_err(err, errlen, "image is too small for the 3D frame's panels");
        return -1;
    }
    lr_view v;
    lr_camera3d_view(&v, &p->camera, x, y + band, aw, ah, p->lo, p->hi);
    lr_view_clip(&v, floor(x), floor(y + band), ceil(x + aw), ceil(y + h));
    double lo, hi;
    lr_panel3d_range(p, &lo, &hi);
    lr_scene3d *s = lr_scene3d_new();
    if (!s || fill_scene(s, &v, p, lo, hi) != 0) {
        lr_scene3d_free(s);
        lu_err(err, errlen, "3D frame: out of memory");
        return -1;
    }
    int cx = (int)floor(x), cy = (int)floor(y + band);
    lr_canvas_clip(c, cx, cy, (int)ceil(x + aw) - cx, (int)ceil(y + h) - cy);
    int rc = lr_scene3d_draw(c, &v, s, err, errlen);
    lr_canvas_unclip(c);
    lr_scene3d_free(s);
    if (rc != 0)
        return -1;
    double bx = x + aw;
    for (int b = 0; b < nb; b++) {
        fig_draw_colourbar(c, &bars[b].p, bx, y + band + 0.1 * ah, y + band + 0.9 * ah, font,
                           bars[b].lo, bars[b].hi);
        bx += fig_colourbar_width(&bars[b].p, font, bars[b].lo, bars[b].hi);
    }
    if (has_text(p->title))
        lr_canvas_text(c, x + 0.5 * aw, y + font, font, LR_FIG_TEXT, LR_ALIGN_CENTER,
                       p->title);
    return 0;
}

/* 0, or -1 with what is wrong with the frame (or that there is none) in
 * err: drawing and rendering refuse alike. */
static int frame_ok(const lr_figure3d *f, char *err, size_t errlen)
{
    return fig_refuse("3D frame: ", f ? figure_problem(f) : "no figure", err, errlen);
}

int lr_figure3d_draw(const lr_figure3d *f, lr_canvas *c, char *err, size_t errlen)
{
    if (frame_ok(f, err, errlen) != 0 ||
        fig_canvas_fits("3D frame: ", c, f->width, f->height, err, errlen) != 0)
        return -1;
    double W = f->width, H = f->height;
    double margin = MARGIN * fmin(W, H), font = fmax(12.0, H / 40.0);
    double band = TEXT_BAND * font;
    double top_band = has_text(f->title) ? band : 0.0;
    double bottom_band = has_text(f->label) ? band : 0.0;
    if (H - 2 * margin - top_band - bottom_band < 0.5 * H)
        top_band = bottom_band = 0.0;   /* tiny: text over the picture */
    int n = (int)f->npanels, rows = f->rows, cols = f->cols;
    if (rows <= 0 && cols <= 0) {
        rows = 1;
        cols = n;
    } else if (rows <= 0) {
        rows = (n + cols - 1) / cols;
    } else if (cols <= 0) {
        cols = (n + rows - 1) / rows;
    }
    if ((size_t)rows * (size_t)cols < f->npanels) {
        lu_err(err, errlen, "3D frame: layout %d x %d has fewer cells than the %d panels",
               rows, cols, n);
        return -1;
    }
    double left = margin, top = margin + top_band;
    double cw = (W - 2 * margin - (cols - 1) * margin) / cols;
    double ch = (H - 2 * margin - top_band - bottom_band - (rows - 1) * margin) / rows;
    lr_canvas_clear(c, LR_FIG_BACKGROUND);
    for (int k = 0; k < n; k++) {
        int r = k / cols, col = k % cols;
        if (draw_panel(c, &f->panels[k], left + col * (cw + margin), top + r * (ch + margin),
                       cw, ch, font, err, errlen) != 0)
            return -1;
    }
    if (has_text(f->label))
        lr_canvas_text(c, margin, H - margin - 0.3 * font, font, LR_FIG_TEXT, LR_ALIGN_LEFT,
                       f->label);
    if (has_text(f->title))
        lr_canvas_text(c, 0.5 * W, margin + font, font, LR_FIG_TEXT, LR_ALIGN_CENTER,
                       f->title);
    return 0;
}

static int draw_figure3d(const void *f, lr_canvas *c, char *err, size_t errlen)
{
    return lr_figure3d_draw(f, c, err, errlen);
}

unsigned char *lr_figure3d_render(const lr_figure3d *f, char *err, size_t errlen)
{
    if (frame_ok(f, err, errlen) != 0)
        return NULL;
    return fig_render(f->backend, f->width, f->height, draw_figure3d, f, err, errlen);
}

int lr_figure3d_write(const lr_figure3d *f, const char *path, char *err, size_t errlen)
{
    if (!f || !path || !*path) {
        lu_err(err, errlen, "cannot write 3D frame: %s", f ? "empty path" : "no frame");
        return -1;
    }
    if (lr_format_of(path) != LR_FORMAT_PNG) {
        lu_err(err, errlen, "cannot write '%s': a 3D frame is written as PNG", path);
        return -1;
    }
    char why[512] = "";
    unsigned char *rgba = lr_figure3d_render(f, why, sizeof why);
    if (!rgba) {
        lu_err(err, errlen, "cannot write '%s': %s", path, why);
        return -1;
    }
    int rc = lr_image_write(path, f->width, f->height, rgba, f->text, f->ntext, err, errlen);
    free(rgba);
    return rc;
}
