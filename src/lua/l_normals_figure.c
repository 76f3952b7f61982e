/* l_normals_figure.c - lamina.figure{...}: a picture of points, normals
 * and phi, panel by panel, as the normals paper draws them (Figs 3-11):
 * phi contours (phi = 1 bold, phi = 0 through the random point), membrane
 * points as open circles, the random point as an asterisk, computed
 * normals solid and exact normals dashed, the element outline; 3D panels
 * show the cube, points and arrows seen from azimuth / elevation.
 *
 * 3D panels are a view of their own (src/render/include/view3d.h): what is drawn
 * into them is kept as a scene and drawn when the figure is written -
 * through OpenGL with a depth buffer (OSMesa or EGL: spheres, shaded cone
 * heads, hidden parts hidden) when lamina has either, otherwise as cairo's
 * orthographic projection in painter's order, with the same camera.
 * `backend = "cairo" | "osmesa" | "egl" | "gl"` (or `lamina run
 * --backend`) chooses; the PNG says which in its "lamina:view3d" text
 * chunk.
 *
 *   local fig = lamina.figure{ width = 800, height = 800, panels = {2, 2},
 *                              title = "...", backend = "osmesa" }
 *   fig:panel{ index = 1, window = {0, 0, 1, 1}, title = "(a)" }
 *   fig:normals{ result = r, points = pts, exact = exact_normals }
 *   fig:write("out/fig.png")
 *
 * Bindings only: the drawing is src/render/include/layers.h. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "l_internal.h"
#include "l_normals.h"
#include "layers.h"
#include "render.h"
#include "view3d.h"

#define MAX_PANELS 36

typedef struct la_panel {
    int set;                    /* a window or box was given */
    lr_view view;
    double px, py, pw, ph;      /* the panel's cell, pixels */
    double font;
    double lo[3], hi[3];        /* its world window (2D) or box (3D) */
    int dim;
    int captions;               /* caption lines drawn so far */
    size_t scene;               /* 3D: its view in la_figure.views, + 1 */
    int axes_outside;           /* 3D: axis names beside the box's outline
                                   (axes = "outside"), not at the far ends */
} la_panel;

/* A 3D panel's view and what was drawn into it, drawn at fig:write. A
 * panel given a new box keeps its old view here too, drawn first. */
typedef struct la_view3d {
    lr_view view;
    lr_scene3d *scene;
} la_view3d;

typedef struct la_figure {
    lr_canvas *canvas;          /* everything but the 3D views */
    int width, height, cols, rows, cur;
    lr_backend view3d;          /* draws the 3D views */
    la_view3d *views;
    size_t nviews, capviews;
    la_panel panels[MAX_PANELS];
} la_figure;

static const lr_rgba BLACK = {0, 0, 0, 1};
static const lr_rgba WHITE = {1, 1, 1, 1};
static const lr_rgba GREY = {0.62, 0.62, 0.62, 1};
static const lr_rgba TEXT = {0.15, 0.15, 0.15, 1};
/* Okabe & Ito: blue for computed normals, vermilion for exact ones */
static const lr_rgba BLUE = {0x00 / 255.0, 0x72 / 255.0, 0xB2 / 255.0, 1};
static const lr_rgba VERMILION = {0xD5 / 255.0, 0x5E / 255.0, 0x00 / 255.0, 1};
static const lr_rgba GREEN = {0x00 / 255.0, 0x9E / 255.0, 0x73 / 255.0, 1};

/* ---- arguments ---------------------------------------------------------- */

static la_figure *check_fig(lua_State *L)
{
    la_figure *f = luaL_checkudata(L, 1, LA_FIGURE);
    if (!f->canvas)
        luaL_error(L, "figure: already freed");
    return f;
}

/* The scene of a 3D panel. */
static lr_scene3d *scene(la_figure *f, const la_panel *p)
{
    return f->views[p->scene - 1].scene;
}

/* A scene call's result: out of memory is a Lua error. */
static void added(lua_State *L, int rc, const char *fn)
{
    if (rc != 0)
        luaL_error(L, "%s: out of memory", fn);
}

static la_panel *current(lua_State *L, la_figure *f, const char *fn)
{
    la_panel *p = &f->panels[f->cur];
    if (!p->set)
        luaL_error(L, "%s: panel %d has no window yet: call fig:panel{window = "
                   "{x0, y0, x1, y1}} (or box = {...} for 3D) first", fn, f->cur + 1);
    return p;
}

/* A drawing method's start: the figure (argument 1), its options
 * (argument 2) checked against keys, and the current panel. */
static la_panel *drawing(lua_State *L, const char *fn, const char *const keys[],
                         la_figure **f)
{
    *f = check_fig(L);
    la_check_keys(L, 2, fn, keys);
    return current(L, *f, fn);
}

static lr_rgba read_colour(lua_State *L, int idx, const char *fn, const char *key,
                           lr_rgba def)
{
    int t = la_getfield(L, idx, key);
    lr_rgba c = def;
    if (t == LUA_TSTRING) {
        static const char *const names[] = {"black", "grey", "computed", "exact",
                                            "green", "white", NULL};
        const lr_rgba cols[] = {BLACK, GREY, BLUE, VERMILION, GREEN, WHITE};
        c = cols[la_option(L, fn, key, lua_tostring(L, -1), names)];
    } else if (t == LUA_TTABLE) {
        int n = (int)lua_rawlen(L, -1);
        if (n != 3 && n != 4)
            luaL_error(L, "%s: '%s' must be a name or {r, g, b[, a]} in 0..1", fn, key);
        double v[4] = {0, 0, 0, 1};
        for (int i = 0; i < n; i++) {
            lua_rawgeti(L, -1, i + 1);
            v[i] = luaL_checknumber(L, -1);
            lua_pop(L, 1);
        }
        c = (lr_rgba){v[0], v[1], v[2], v[3]};
    } else if (t != LUA_TNIL) {
        luaL_error(L, "%s: '%s' must be a colour name or {r, g, b}", fn, key);
    }
    lua_pop(L, 1);
    return c;
}

/* A list of points {{x, y[, z]}, ...} at key into SoA arrays kept alive in
 * a userdata left on the stack. Returns the count; dim from the panel. */
static size_t read_list(lua_State *L, int idx, const char *fn, const char *key,
                        int dim, double *p[3])
{
    la_getfield(L, idx, key);
    if (!lua_istable(L, -1))
        luaL_error(L, "%s: '%s' must be a list of {x, y%s}", fn, key,
                   dim == 3 ? ", z" : "");
    size_t n = lua_rawlen(L, -1);
    double *buf = lua_newuserdatauv(L, sizeof(double) * 3 * (n ? n : 1), 0);
    lua_insert(L, -2);
    for (int a = 0; a < 3; a++)
        p[a] = buf + (size_t)a * n;
    for (size_t i = 0; i < n; i++) {
        lua_rawgeti(L, -1, (lua_Integer)i + 1);
        int len = lua_istable(L, -1) ? (int)lua_rawlen(L, -1) : 0;
        if (len < dim)
            luaL_error(L, "%s: %s[%d] must be {x, y%s}", fn, key, (int)i + 1,
                       dim == 3 ? ", z" : "");
        for (int a = 0; a < 3; a++) {
            p[a][i] = 0.0;
            if (a < dim) {
                lua_rawgeti(L, -1, a + 1);
                p[a][i] = luaL_checknumber(L, -1);
                lua_pop(L, 1);
            }
        }
        lua_pop(L, 1);
    }
    lua_pop(L, 1);
    return n;
}

/* {x0, y0, x1, y1} or {x0, y0, z0, x1, y1, z1} at key; returns dim or 0 if
 * absent. */
static int read_box(lua_State *L, int idx, const char *fn, const char *key,
                    double lo[3], double hi[3])
{
    int t = la_getfield(L, idx, key);
    if (t == LUA_TNIL) {
        lua_pop(L, 1);
        return 0;
    }
    int len = t == LUA_TTABLE ? (int)lua_rawlen(L, -1) : 0;
    if (len != 4 && len != 6)
        luaL_error(L, "%s: '%s' must be {x0, y0, x1, y1} or {x0, y0, z0, x1, y1, z1}",
                   fn, key);
    int dim = len / 2;
    double v[6];
    for (int i = 0; i < len; i++) {
        lua_rawgeti(L, -1, i + 1);
        v[i] = luaL_checknumber(L, -1);
        lua_pop(L, 1);
    }
    lua_pop(L, 1);
    lo[2] = hi[2] = 0;
    for (int a = 0; a < dim; a++) {
        lo[a] = v[a];
        hi[a] = v[dim + a];
        if (!(hi[a] > lo[a]) || !isfinite(lo[a]) || !isfinite(hi[a]))
            luaL_error(L, "%s: '%s' is empty along axis %d", fn, key, a + 1);
    }
    return dim;
}

/* ---- lamina.figure{...} ------------------------------------------------- */

/* What draws the 3D panels: backend = "cairo" | "osmesa" | "egl" | "gl";
 * else `lamina run --backend`; else OpenGL when this lamina has it: OSMesa
 * first (the pictures stay what they were where it is built; EGL's differ
 * from them by a level in a few pixels), then EGL, then cairo. */
static lr_backend view3d_backend(lua_State *L, const char *fn)
{
    const char *name = la_opt_string(L, 1, fn, "backend", NULL);
    const lamina_run *run = la_run(L);
    lr_backend b = LR_BACKEND_CAIRO;
    char why[512];
    if (!name && run && run->backend)
        name = run->backend;
    if (!name) {
        if (lr_backend_check(LR_BACKEND_OSMESA, NULL, 0) == 0)
            return LR_BACKEND_OSMESA;
        return lr_backend_check(LR_BACKEND_EGL, NULL, 0) == 0 ? LR_BACKEND_EGL
                                                              : LR_BACKEND_CAIRO;
    }
    if (lr_backend_parse(name, &b, why, sizeof why) != 0)
        luaL_error(L, "%s: %s", fn, why);
    if (lr_backend_check(b, why, sizeof why) != 0)
        luaL_error(L, "%s: backend = \"%s\": %s", fn, name, why);
    return b;
}

int la_figure_new(lua_State *L)
{
    static const char *const keys[] = {"width", "height", "panels", "title",
                                       "backend", NULL};
    const char *fn = "lamina.figure";
    if (lua_isnoneornil(L, 1))
        lua_newtable(L);
    la_check_keys(L, 1, fn, keys);
    double w = la_opt_number(L, 1, fn, "width", 800);
    double h = la_opt_number(L, 1, fn, "height", 800);
    if (!(w >= 16 && w <= 16384) || !(h >= 16 && h <= 16384) || w != floor(w) ||
        h != floor(h))
        return luaL_error(L, "%s: width and height must be whole numbers in "
                          "[16, 16384]", fn);
    double cols = 1, rows = 1;
    if (la_has(L, 1, "panels"))
        la_pair(L, 1, fn, "panels", &cols, &rows);
    if (!(cols >= 1) || !(rows >= 1) || cols != floor(cols) || rows != floor(rows) ||
        cols * rows > MAX_PANELS)
        return luaL_error(L, "%s: 'panels' must be {columns, rows}, at most %d panels",
                          fn, MAX_PANELS);
    const char *title = la_opt_string(L, 1, fn, "title", NULL);
    lr_backend view3d = view3d_backend(L, fn);
    la_figure *f = lua_newuserdatauv(L, sizeof *f, 0);
    memset(f, 0, sizeof *f);
    luaL_setmetatable(L, LA_FIGURE);
    f->view3d = view3d;
    char err[256];
    f->canvas = lr_canvas_cairo_new((int)w, (int)h, err, sizeof err);
    if (!f->canvas)
        return luaL_error(L, "%s: %s", fn, err);
    lr_canvas_clear(f->canvas, WHITE);
    f->width = (int)w;
    f->height = (int)h;
    f->cols = (int)cols;
    f->rows = (int)rows;
    double font = fmax(13.0, fmin(w, h) / 40.0);
    double top = 0;
    if (title && *title) {
        top = 2.0 * font;
        lr_canvas_text(f->canvas, 0.5 * w, 1.4 * font, 1.1 * font, TEXT,
                       LR_ALIGN_CENTER, title);
    }
    double cw = w / cols, ch = (h - top) / rows;
    for (int r = 0; r < f->rows; r++)
        for (int c = 0; c < f->cols; c++) {
            la_panel *p = &f->panels[r * f->cols + c];
            p->px = c * cw;
            p->py = top + r * ch;
            p->pw = cw;
            p->ph = ch;
            p->font = fmax(11.0, fmin(cw, ch) / 34.0);
        }
    return 1;
}

#define BAND 1.7                /* title and caption lines, in font sizes */

/* Baseline of caption line k under panel p (two lines fit). */
static double caption_y(const la_panel *p, int k)
{
    return p->py + p->ph - 2.0 * BAND * p->font + (k + 1) * 1.3 * p->font;
}

/* fig:panel{index =, window = | box =, azimuth =, elevation =, axes =,
 * title =, caption =}: selects a panel and sets its view. */
static int l_panel(lua_State *L)
{
    static const char *const keys[] = {"index", "window", "box", "azimuth",
                                       "elevation", "axes", "title", "caption", NULL};
    static const char *const axes_names[] = {"ends", "outside", NULL};
    const char *fn = "figure:panel";
    la_figure *f = check_fig(L);
    la_check_keys(L, 2, fn, keys);
    /* read before the scene is made: an error here leaks nothing */
    int axes_outside = la_option(L, fn, "axes", la_opt_string(L, 2, fn, "axes", "ends"),
                                 axes_names);
    double k = la_opt_number(L, 2, fn, "index", f->cur + 1);
    if (!(k >= 1 && k <= f->cols * f->rows) || k != floor(k))
        return luaL_error(L, "%s: index must be 1..%d", fn, f->cols * f->rows);
    f->cur = (int)k - 1;
    la_panel *p = &f->panels[f->cur];
    double lo[3], hi[3];
    int d2 = read_box(L, 2, fn, "window", lo, hi);
    int d3 = read_box(L, 2, fn, "box", lo, hi);
    if (d2 && d2 != 2)
        return luaL_error(L, "%s: 'window' is {x0, y0, x1, y1}; 3D uses 'box'", fn);
    if (d3 && d3 != 3)
        return luaL_error(L, "%s: 'box' is {x0, y0, z0, x1, y1, z1}; 2D uses 'window'",
                          fn);
    if (d2 && d3)
        return luaL_error(L, "%s: give 'window' (2D) or 'box' (3D), not both", fn);
    double band = BAND * p->font;
    double vx = p->px, vy = p->py + band, vw = p->pw, vh = p->ph - 3.0 * band;
    double m = 0.05 * fmin(vw, vh);
    if (d2 || d3) {
        lr_view view;
        la_view3d *e = NULL;
        if (d3) {
            double az = la_opt_number(L, 2, fn, "azimuth", -60);
            double el = la_opt_number(L, 2, fn, "elevation", 25);
            if (!isfinite(az) || !(el >= -90 && el <= 90))
                return luaL_error(L, "%s: 'azimuth' must be finite and 'elevation' "
                                  "in [-90, 90] degrees", fn);
            lr_view_3d(&view, vx + m, vy + m, vw - 2 * m, vh - 2 * m, lo, hi, az, el);
            /* room for its scene first: the panel changes only when all is well */
            if (f->nviews == f->capviews) {
                size_t cap = f->capviews ? 2 * f->capviews : 4;
                la_view3d *q = realloc(f->views, cap * sizeof *q);
                if (!q)
                    return luaL_error(L, "%s: out of memory", fn);
                f->views = q;
                f->capviews = cap;
            }
            e = &f->views[f->nviews];
            e->scene = lr_scene3d_new();
            if (!e->scene)
                return luaL_error(L, "%s: out of memory", fn);
        } else {
            lr_view_2d(&view, vx + m, vy + m, vw - 2 * m, vh - 2 * m, lo[0], lo[1],
                       hi[0], hi[1]);
        }
        /* drawing stays in the panel, off its title and caption lines, and
         * in 2D within the margin around the window */
        double c0 = vx, c1 = vy, c2 = vx + vw, c3 = vy + vh;
        if (!d3) {
            double a[3] = {lo[0], hi[1], 0}, b[3] = {hi[0], lo[1], 0}, ax, ay, bx, by;
            lr_view_map(&view, a, &ax, &ay);
            lr_view_map(&view, b, &bx, &by);
            c0 = fmax(c0, ax - m);
            c1 = fmax(c1, ay - m);
            c2 = fmin(c2, bx + m);
            c3 = fmin(c3, by + m);
        }
        lr_view_clip(&view, c0, c1, c2, c3);
        p->set = 1;
        p->dim = d3 ? 3 : 2;
        p->axes_outside = axes_outside;
        memcpy(p->lo, lo, sizeof lo);
        memcpy(p->hi, hi, sizeof hi);
        p->captions = 0;
        p->view = view;
        p->scene = 0;
        if (e) {
            e->view = view;
            p->scene = ++f->nviews;
        }
    }
    const char *title = la_opt_string(L, 2, fn, "title", NULL);
    if (title)
        lr_canvas_text(f->canvas, p->px + 0.5 * p->pw, p->py + 1.25 * p->font,
                       p->font, TEXT, LR_ALIGN_CENTER, title);
    const char *cap = la_opt_string(L, 2, fn, "caption", NULL);
    if (cap) {
        lr_canvas_text(f->canvas, p->px + 0.5 * p->pw, caption_y(p, p->captions),
                       0.9 * p->font, TEXT, LR_ALIGN_CENTER, cap);
        p->captions++;
    }
    lua_settop(L, 1);
    return 1;
}

/* fig:caption{text = "..."}: one more line under the current panel. */
static int l_caption(lua_State *L)
{
    static const char *const keys[] = {"text", NULL};
    la_figure *f = check_fig(L);
    la_check_keys(L, 2, "figure:caption", keys);
    la_panel *p = &f->panels[f->cur];
    const char *t = la_opt_string(L, 2, "figure:caption", "text", "");
    lr_canvas_text(f->canvas, p->px + 0.5 * p->pw, caption_y(p, p->captions),
                   0.9 * p->font, TEXT, LR_ALIGN_CENTER, t);
    p->captions++;
    lua_settop(L, 1);
    return 1;
}

/* The element: a rectangle, or in 3D the box with its hidden edges dashed
 * and the axis names at the far ends of the three edges from lo. */
static void draw_box(lua_State *L, la_figure *f, const la_panel *p,
                     const double lo[3], const double hi[3], double width,
                     lr_rgba colour)
{
    if (!p->view.is3d) {
        lr_layer_box(f->canvas, &p->view, lo, hi, width, colour);
        return;
    }
    lr_scene3d *s = scene(f, p);
    added(L, lr_scene3d_box(s, lo, hi, width, colour), "figure");
    static const char *const names[] = {"x", "y", "z"};
    double at[3][3], out[3][2];
    if (p->axes_outside)
        lr_view_axis_places(&p->view, lo, hi, at, out);
    for (int a = 0; a < 3; a++) {
        double q[3] = {lo[0], lo[1], lo[2]}, dx = 0.0, dy = 0.0;
        q[a] = hi[a] + 0.1 * (hi[a] - lo[a]);
        if (p->axes_outside) {      /* a font size off the outline's edge */
            memcpy(q, at[a], sizeof q);
            dx = p->font * out[a][0];
            dy = p->font * out[a][1];
        }
        added(L, lr_scene3d_text(s, q, dx, dy + 0.35 * p->font, p->font, TEXT,
                                 LR_ALIGN_CENTER, names[a]), "figure");
    }
}

/* fig:outline{box =, width =, colour =}: the element (a rectangle, or the
 * cube with hidden edges dashed); default the panel's own window/box. */
static int l_outline(lua_State *L)
{
    static const char *const keys[] = {"box", "width", "colour", NULL};
    const char *fn = "figure:outline";
    la_figure *f = check_fig(L);
    if (lua_isnoneornil(L, 2))
        lua_newtable(L);
    la_check_keys(L, 2, fn, keys);
    la_panel *p = current(L, f, fn);
    double lo[3], hi[3];
    if (!read_box(L, 2, fn, "box", lo, hi)) {
        memcpy(lo, p->lo, sizeof lo);
        memcpy(hi, p->hi, sizeof hi);
    }
    draw_box(L, f, p, lo, hi, la_opt_number(L, 2, fn, "width", 1.5),
             read_colour(L, 2, fn, "colour", BLACK));
    lua_settop(L, 1);
    return 1;
}

/* fig:grid{box =, cells = {nx, ny}, colour =}: cell lines (2D). */
static int l_grid(lua_State *L)
{
    static const char *const keys[] = {"box", "cells", "colour", "width", NULL};
    const char *fn = "figure:grid";
    la_figure *f;
    la_panel *p = drawing(L, fn, keys, &f);
    double lo[3], hi[3], nx, ny;
    if (read_box(L, 2, fn, "box", lo, hi) != 2)
        return luaL_error(L, "%s: 'box' = {x0, y0, x1, y1} is required", fn);
    la_pair(L, 2, fn, "cells", &nx, &ny);
    if (!(nx >= 1 && ny >= 1 && nx <= 4096 && ny <= 4096))
        return luaL_error(L, "%s: 'cells' must be {nx, ny} in 1..4096", fn);
    lr_rgba k = read_colour(L, 2, fn, "colour", GREY);
    double w = la_opt_number(L, 2, fn, "width", 1.0);
    for (int i = 0; i <= (int)nx; i++)
        for (int j = 0; j <= (int)ny; j++) {
            double a[3] = {lo[0] + (hi[0] - lo[0]) * i / nx, lo[1], 0};
            double b[3] = {a[0], hi[1], 0};
            double c[3] = {lo[0], lo[1] + (hi[1] - lo[1]) * j / ny, 0};
            double d[3] = {hi[0], c[1], 0};
            double ax, ay, bx, by;
            if (p->view.is3d) {
                if (j == 0)
                    added(L, lr_scene3d_line(scene(f, p), a, b, w, k, 0.0), fn);
                if (i == 0)
                    added(L, lr_scene3d_line(scene(f, p), c, d, w, k, 0.0), fn);
                continue;
            }
            if (j == 0) {
                lr_view_map(&p->view, a, &ax, &ay);
                lr_view_map(&p->view, b, &bx, &by);
                lr_view_line(f->canvas, &p->view, ax, ay, bx, by, w, k, 0.0);
            }
            if (i == 0) {
                lr_view_map(&p->view, c, &ax, &ay);
                lr_view_map(&p->view, d, &bx, &by);
                lr_view_line(f->canvas, &p->view, ax, ay, bx, by, w, k, 0.0);
            }
        }
    lua_settop(L, 1);
    return 1;
}

/* ---- contours ----------------------------------------------------------------- */

/* phi sampled on (s+1)^2 points over lo..hi: from a lamina.normals result
 * (in C), or a Lua function f(x, y) -> number (nil: no value). */
static double *sample(lua_State *L, int fidx, const la_nfield *field, int s,
                      const double lo[3], const double hi[3])
{
    size_t n = (size_t)(s + 1) * (size_t)(s + 1);
    double *v = lua_newuserdatauv(L, sizeof(double) * n, 0);
    for (int j = 0; j <= s; j++)
        for (int i = 0; i <= s; i++) {
            double x[3] = {lo[0] + (hi[0] - lo[0]) * i / s,
                           lo[1] + (hi[1] - lo[1]) * j / s, 0.0};
            double *out = &v[i + (s + 1) * j];
            if (field) {
                *out = la_nfield_phi(field, x);
                continue;
            }
            lua_pushvalue(L, fidx);
            lua_pushnumber(L, x[0]);
            lua_pushnumber(L, x[1]);
            lua_call(L, 2, 1);
            *out = lua_isnil(L, -1) ? NAN : luaL_checknumber(L, -1);
            lua_pop(L, 1);
        }
    return v;
}

static void draw_contours(lua_State *L, la_figure *f, la_panel *p, const double *v,
                          int s, const double lo[3], const double hi[3], int lidx,
                          double bold)
{
    size_t nl = lua_rawlen(L, lidx);
    for (size_t k = 1; k <= nl; k++) {
        lua_rawgeti(L, lidx, (lua_Integer)k);
        double level = luaL_checknumber(L, -1);
        lua_pop(L, 1);
        int is_bold = level == bold, is_zero = level == 0.0;
        lr_layer_contour(f->canvas, &p->view, v, s, s, lo[0], lo[1], hi[0], hi[1],
                         level, is_bold ? 2.6 : is_zero ? 1.3 : 0.8,
                         is_bold || is_zero ? BLACK : GREY);
    }
}

static void default_levels(lua_State *L)
{
    lua_createtable(L, 11, 0);
    for (int k = 0; k <= 10; k++) {
        lua_pushnumber(L, -2.0 + 0.5 * k);
        lua_rawseti(L, -2, k + 1);
    }
}

/* fig:contours{phi = result | function, levels = {...}, bold = 1, box =,
 * samples = 160}: marching squares on phi sampled over box (default: the
 * result's box, else the panel window). */
static int l_contours(lua_State *L)
{
    static const char *const keys[] = {"phi", "levels", "bold", "box", "samples", NULL};
    const char *fn = "figure:contours";
    la_figure *f;
    la_panel *p = drawing(L, fn, keys, &f);
    if (p->view.is3d)
        return luaL_error(L, "%s: contours are drawn in 2D panels only", fn);
    la_getfield(L, 2, "phi");
    int fidx = lua_gettop(L);
    la_nfield *field = la_to_nfield(L, fidx);
    if (!field && !lua_isfunction(L, fidx))
        return luaL_error(L, "%s: 'phi' must be a lamina.normals result or a "
                          "function f(x, y)", fn);
    if (field && field->dim != 2)
        return luaL_error(L, "%s: the result is 3D; contours need a 2D result", fn);
    double lo[3], hi[3];
    if (!read_box(L, 2, fn, "box", lo, hi)) {
        memcpy(lo, field ? field->lo : p->lo, sizeof lo);
        memcpy(hi, field ? field->hi : p->hi, sizeof hi);
    }
    double s = la_opt_number(L, 2, fn, "samples", 160);
    if (!(s >= 2 && s <= 2000) || s != floor(s))
        return luaL_error(L, "%s: 'samples' must be a whole number in [2, 2000]", fn);
    if (la_getfield(L, 2, "levels") == LUA_TNIL) {
        lua_pop(L, 1);
        default_levels(L);
    } else if (!lua_istable(L, -1)) {
        return luaL_error(L, "%s: 'levels' must be a list of numbers", fn);
    }
    int lidx = lua_gettop(L);
    double *v = sample(L, fidx, field, (int)s, lo, hi);
    draw_contours(L, f, p, v, (int)s, lo, hi, lidx, la_opt_number(L, 2, fn, "bold", 1));
    lua_settop(L, 1);
    return 1;
}

/* ---- points, arrows, lines, text ------------------------------------------------- */

/* fig:points{points =, style = "circle" | "asterisk" | "dot", size =,
 * colour =, width =} */
static int l_points(lua_State *L)
{
    static const char *const keys[] = {"points", "style", "size", "colour", "width",
                                       NULL};
    static const char *const styles[] = {"circle", "asterisk", "dot", NULL};
    const char *fn = "figure:points";
    la_figure *f;
    la_panel *p = drawing(L, fn, keys, &f);
    double *q[3];
    size_t n = read_list(L, 2, fn, "points", p->dim, q);
    int style = la_option(L, fn, "style", la_opt_string(L, 2, fn, "style", "circle"),
                          styles);
    double size = la_opt_number(L, 2, fn, "size", style == 1 ? 14 : 6);
    double w = la_opt_number(L, 2, fn, "width", 1.4);
    lr_rgba k = read_colour(L, 2, fn, "colour", BLACK);
    const double *const cq[3] = {q[0], q[1], q[2]};
    if (p->view.is3d) {
        lr_scene3d *s = scene(f, p);
        if (style == 0)
            added(L, lr_scene3d_circles(s, n, cq, size, w, k), fn);
        else if (style == 2)
            added(L, lr_scene3d_dots(s, n, cq, size, k), fn);
        else
            for (size_t i = 0; i < n; i++) {
                double x[3] = {q[0][i], q[1][i], q[2][i]};
                added(L, lr_scene3d_asterisk(s, x, size, w, k), fn);
            }
    } else if (style == 0)
        lr_layer_circles(f->canvas, &p->view, n, p->dim, cq, size, w, k);
    else if (style == 2)
        lr_layer_dots(f->canvas, &p->view, n, p->dim, cq, size, k);
    else
        for (size_t i = 0; i < n; i++) {
            double x[3] = {q[0][i], q[1][i], q[2][i]};
            lr_layer_asterisk(f->canvas, &p->view, x, size, w, k);
        }
    lua_settop(L, 1);
    return 1;
}

static double panel_size(const la_panel *p)
{
    double s = 0;
    for (int a = 0; a < p->dim; a++)
        s = fmax(s, p->hi[a] - p->lo[a]);
    return s;
}

static void arrows(lua_State *L, la_figure *f, la_panel *p, int at, int dir,
                   double length, double width, lr_rgba k, int dashed, const char *fn)
{
    double *q[3], *d[3];
    size_t n = read_list(L, at, fn, "at", p->dim, q);
    size_t m = read_list(L, dir, fn, "dir", p->dim, d);
    if (m != n)
        luaL_error(L, "%s: %d points but %d directions", fn, (int)n, (int)m);
    const double *const cq[3] = {q[0], q[1], q[2]}, *const cd[3] = {d[0], d[1], d[2]};
    if (p->view.is3d)
        added(L, lr_scene3d_arrows(scene(f, p), n, cq, cd, length, width,
                                   fmax(7.0, 3.5 * width), k, dashed ? 5.0 : 0.0), fn);
    else
        lr_layer_arrows(f->canvas, &p->view, n, p->dim, cq, cd, length, width,
                        fmax(7.0, 3.5 * width), k, dashed ? 5.0 : 0.0);
}

/* fig:arrows{at =, dir =, length =, style = "solid" | "dashed", colour =,
 * width =}: arrows from the points along the (unit) directions. */
static int l_arrows(lua_State *L)
{
    static const char *const keys[] = {"at", "dir", "length", "style", "colour",
                                       "width", NULL};
    static const char *const styles[] = {"solid", "dashed", NULL};
    const char *fn = "figure:arrows";
    la_figure *f;
    la_panel *p = drawing(L, fn, keys, &f);
    int dashed = la_option(L, fn, "style", la_opt_string(L, 2, fn, "style", "solid"),
                           styles);
    double len = la_opt_number(L, 2, fn, "length", 0.15 * panel_size(p));
    lr_rgba k = read_colour(L, 2, fn, "colour", dashed ? VERMILION : BLUE);
    arrows(L, f, p, 2, 2, len, la_opt_number(L, 2, fn, "width", 1.6), k, dashed, fn);
    lua_settop(L, 1);
    return 1;
}

/* fig:polyline{points =, colour =, width =, dashed =} */
static int l_polyline(lua_State *L)
{
    static const char *const keys[] = {"points", "colour", "width", "dashed", NULL};
    const char *fn = "figure:polyline";
    la_figure *f;
    la_panel *p = drawing(L, fn, keys, &f);
    double *q[3];
    size_t n = read_list(L, 2, fn, "points", p->dim, q);
    la_getfield(L, 2, "dashed");
    int dashed = lua_toboolean(L, -1);
    lua_pop(L, 1);
    const double *const cq[3] = {q[0], q[1], q[2]};
    double w = la_opt_number(L, 2, fn, "width", 1.0);
    lr_rgba k = read_colour(L, 2, fn, "colour", GREY);
    if (p->view.is3d)
        added(L, lr_scene3d_polyline(scene(f, p), n, cq, w, k, dashed ? 4.0 : 0.0), fn);
    else
        lr_layer_polyline(f->canvas, &p->view, n, p->dim, cq, w, k, dashed ? 4.0 : 0.0);
    lua_settop(L, 1);
    return 1;
}

/* fig:text{text =, at = {x, y[, z]}, size =, colour =, align =} */
static int l_text(lua_State *L)
{
    static const char *const keys[] = {"text", "at", "size", "colour", "align", NULL};
    static const char *const aligns[] = {"left", "center", "right", NULL};
    const char *fn = "figure:text";
    la_figure *f;
    la_panel *p = drawing(L, fn, keys, &f);
    const char *t = la_opt_string(L, 2, fn, "text", NULL);
    if (!t)
        return luaL_error(L, "%s: 'text' is required", fn);
    double v[3] = {0, 0, 0}, x, y;
    la_getfield(L, 2, "at");
    if (!lua_istable(L, -1) || (int)lua_rawlen(L, -1) < p->dim)
        return luaL_error(L, "%s: 'at' must be a point {x, y%s}", fn,
                          p->dim == 3 ? ", z" : "");
    for (int a = 0; a < p->dim; a++) {
        lua_rawgeti(L, -1, a + 1);
        v[a] = luaL_checknumber(L, -1);
        lua_pop(L, 1);
    }
    lua_pop(L, 1);
    int al = la_option(L, fn, "align", la_opt_string(L, 2, fn, "align", "left"), aligns);
    double size = la_opt_number(L, 2, fn, "size", 0.9 * p->font);
    lr_rgba k = read_colour(L, 2, fn, "colour", TEXT);
    if (p->view.is3d) {
        added(L, lr_scene3d_text(scene(f, p), v, 0.0, 0.0, size, k, (lr_align)al, t), fn);
    } else {
        lr_view_map(&p->view, v, &x, &y);
        lr_canvas_text(f->canvas, x, y, size, k, (lr_align)al, t);
    }
    lua_settop(L, 1);
    return 1;
}

/* ---- the paper's composite ------------------------------------------------------- */

/* The asterisks of a result's random point (black) and phi = 2 point
 * (vermilion), if present. */
static void draw_random_points(lua_State *L, la_figure *f, la_panel *p, int tbl)
{
    for (int which = 0; which < 2; which++) {
        if (la_getfield(L, tbl, which ? "phi2_point" : "random_point") == LUA_TTABLE) {
            double x[3] = {0, 0, 0};
            for (int a = 0; a < p->dim; a++) {
                lua_rawgeti(L, -1, a + 1);
                x[a] = lua_tonumber(L, -1);
                lua_pop(L, 1);
            }
            if (p->view.is3d)
                added(L, lr_scene3d_asterisk(scene(f, p), x, 14, 1.5,
                                             which ? VERMILION : BLACK), "figure:normals");
            else
                lr_layer_asterisk(f->canvas, &p->view, x, 14, 1.5,
                                  which ? VERMILION : BLACK);
        }
        lua_pop(L, 1);
    }
}

/* Element outlines of a result: its box, or every element's block. */
static void draw_elements(lua_State *L, la_figure *f, la_panel *p, int res)
{
    int t = la_getfield(L, res, "elements");
    if (t == LUA_TTABLE) {
        size_t n = lua_rawlen(L, -1);
        for (size_t k = 1; k <= n; k++) {
            lua_rawgeti(L, -1, (lua_Integer)k);
            double lo[3], hi[3];
            if (read_box(L, lua_gettop(L), "figure:normals", "box", lo, hi))
                draw_box(L, f, p, lo, hi, 1.2, BLACK);
            draw_random_points(L, f, p, lua_gettop(L));
            lua_pop(L, 1);
        }
    } else {
        double lo[3], hi[3];
        if (read_box(L, res, "figure:normals", "box", lo, hi))
            draw_box(L, f, p, lo, hi, 1.5, BLACK);
    }
    lua_pop(L, 1);
}

/* fig:normals{result =, points =, exact =, length =, levels =, samples =}:
 * what [N] Figs 3-11 show - contours of phi (2D), the element, exact
 * normals dashed, computed normals solid, membrane points as open circles,
 * the random point as an asterisk. */
static int l_normals(lua_State *L)
{
    static const char *const keys[] = {"result", "points", "exact", "length", "levels",
                                       "samples", NULL};
    const char *fn = "figure:normals";
    la_figure *f;
    la_panel *p = drawing(L, fn, keys, &f);
    if (la_getfield(L, 2, "result") != LUA_TTABLE)
        return luaL_error(L, "%s: 'result' must be what lamina.normals returned", fn);
    int res = lua_gettop(L);
    double len = la_opt_number(L, 2, fn, "length", 0.15 * panel_size(p));
    la_nfield *field = la_to_nfield(L, res);
    if (field && !p->view.is3d) {
        lua_createtable(L, 0, 4);
        lua_pushvalue(L, res);
        lua_setfield(L, -2, "phi");
        for (int k = 0; k < 2; k++) {
            const char *key = k ? "samples" : "levels";
            la_getfield(L, 2, key);
            lua_setfield(L, -2, key);
        }
        lua_pushcfunction(L, l_contours);
        lua_pushvalue(L, 1);
        lua_pushvalue(L, -3);
        lua_call(L, 2, 0);
        lua_pop(L, 1);
    }
    draw_elements(L, f, p, res);
    if (!la_has(L, 2, "points"))
        return luaL_error(L, "%s: 'points' (the membrane points given to "
                          "lamina.normals) is required", fn);
    /* a table {at = points, dir = ...} for the arrow reader */
    lua_createtable(L, 0, 2);
    int args = lua_gettop(L);
    la_getfield(L, 2, "points");
    lua_setfield(L, args, "at");
    if (la_has(L, 2, "exact")) {
        la_getfield(L, 2, "exact");
        lua_setfield(L, args, "dir");
        arrows(L, f, p, args, args, len, 1.5, VERMILION, 1, fn);
    }
    la_getfield(L, res, "normals");
    lua_setfield(L, args, "dir");
    arrows(L, f, p, args, args, len, 1.8, BLUE, 0, fn);
    double *q[3];
    size_t n = read_list(L, 2, fn, "points", p->dim, q);
    const double *const cq[3] = {q[0], q[1], q[2]};
    if (p->view.is3d)
        added(L, lr_scene3d_circles(scene(f, p), n, cq, 6.0, 1.4, BLACK), fn);
    else
        lr_layer_circles(f->canvas, &p->view, n, p->dim, cq, 6.0, 1.4, BLACK);
    draw_random_points(L, f, p, res);
    lua_settop(L, 1);
    return 1;
}

/* ---- output ----------------------------------------------------------------------- */

/* Each 3D view drawn alone on a canvas of its clip rectangle, through the
 * figure's 3D backend, and laid over the figure's pixels; the figure's own
 * canvas is left as it was, so a later write draws the views again. */
static int draw_views(la_figure *f, unsigned char *rgba, char *err, size_t errlen)
{
    for (size_t i = 0; i < f->nviews; i++) {
        const la_view3d *e = &f->views[i];
        if (lr_scene3d_count(e->scene) == 0)
            continue;
        lr_view v = e->view;
        int x0 = (int)fmax(0.0, floor(v.clip[0])), y0 = (int)fmax(0.0, floor(v.clip[1]));
        int x1 = (int)fmin(f->width, ceil(v.clip[2]));
        int y1 = (int)fmin(f->height, ceil(v.clip[3]));
        if (x1 <= x0 || y1 <= y0)
            continue;
        lr_canvas *c = lr_canvas_new(f->view3d, x1 - x0, y1 - y0, err, errlen);
        if (!c)
            return -1;
        lr_view_offset(&v, -x0, -y0);
        if (lr_scene3d_draw(c, &v, e->scene, err, errlen) != 0) {
            lr_canvas_free(c);
            return -1;
        }
        unsigned char *layer = lr_canvas_read_rgba(c);
        lr_canvas_free(c);
        if (!layer) {
            snprintf(err, errlen, "the 3D view could not be drawn (%s failed or out of "
                     "memory)", lr_backend_name(f->view3d));
            return -1;
        }
        lr_rgba_over(rgba, f->width, f->height, layer, x1 - x0, y1 - y0, x0, y0);
        free(layer);
    }
    return 0;
}

/* fig:write(path) or fig:write{file = path}: the PNG, atomically, with the
 * provenance of sim:frame (Software, lamina:script, -hash, lamina:set) and,
 * when it has 3D panels, what drew them (lamina:view3d = cairo | osmesa | egl). */
static int l_write(lua_State *L)
{
    const char *fn = "figure:write";
    la_figure *f = check_fig(L);
    const char *file = NULL;
    if (lua_type(L, 2) == LUA_TSTRING) {
        file = la_check_output_path(L, fn, 2);
    } else {
        static const char *const keys[] = {"file", NULL};
        la_check_keys(L, 2, fn, keys);
        file = la_opt_output_path(L, 2, fn, "file");
    }
    if (!file || !*file)
        return luaL_error(L, "%s: a file name is required", fn);
    la_prov prov;
    la_provenance(L, &prov);
    unsigned char *rgba = lr_canvas_read_rgba(f->canvas);
    if (!rgba)
        return luaL_error(L, "%s: the drawing failed (cairo error or out of memory)",
                          fn);
    char err[512];
    if (draw_views(f, rgba, err, sizeof err) != 0) {
        free(rgba);
        return luaL_error(L, "%s: %s", fn, err);
    }
    lr_text_chunk text[5];
    memcpy(text, prov.text, sizeof prov.text);
    size_t ntext = 4;
    if (f->nviews) {
        text[4].key = "lamina:view3d";
        text[4].value = lr_backend_name(f->view3d);
        ntext = 5;
    }
    int rc = lr_image_write(file, f->width, f->height, rgba, text, ntext, err, sizeof err);
    free(rgba);
    if (rc)
        return luaL_error(L, "%s: %s", fn, err);
    la_note_image(L, file);
    lua_pushstring(L, file);
    return 1;
}

static int l_gc(lua_State *L)
{
    la_figure *f = luaL_checkudata(L, 1, LA_FIGURE);
    lr_canvas_free(f->canvas);
    f->canvas = NULL;
    for (size_t i = 0; i < f->nviews; i++)
        lr_scene3d_free(f->views[i].scene);
    free(f->views);
    f->views = NULL;
    f->nviews = f->capviews = 0;
    return 0;
}

static int l_tostring(lua_State *L)
{
    la_figure *f = luaL_checkudata(L, 1, LA_FIGURE);
    lua_pushfstring(L, "lamina.figure (%dx%d, %d panel%s)", f->width, f->height,
                    f->cols * f->rows, f->cols * f->rows == 1 ? "" : "s");
    return 1;
}

void la_open_figure(lua_State *L)
{
    static const luaL_Reg methods[] = {{"panel", l_panel},       {"caption", l_caption},
                                       {"outline", l_outline},   {"grid", l_grid},
                                       {"contours", l_contours}, {"points", l_points},
                                       {"arrows", l_arrows},     {"polyline", l_polyline},
                                       {"text", l_text},         {"normals", l_normals},
                                       {"write", l_write},       {NULL, NULL}};
    static const luaL_Reg meta[] = {{"__gc", l_gc}, {"__tostring", l_tostring}, {NULL, NULL}};
    la_new_class(L, LA_FIGURE, meta, methods);
    lua_pop(L, 1);
}
