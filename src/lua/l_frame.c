/* l_frame.c - sim:frame{...}: the simulation's state drawn to a PNG (or an
 * SVG / PDF), as one panel or several (docs/api.md).
 *
 * The binding only gathers what figure.h's lr_figure asks for; the panels'
 * keys are read in l_frame_panel.c, the drawing is src/render's. Every
 * file carries provenance (docs/design.md, "Provenance"). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "l_frame_common.h"
#include "l_frame_panel.h"
#include "l_internal.h"
#include "render.h"

/* backend = "cairo" | "osmesa" | "egl" | "gl" (EGL, else OSMesa); else
 * `lamina run --backend`; else cairo. SVG and PDF are cairo's: a run-wide
 * GL backend does not apply to them, an explicit one is refused when the
 * file is written. */
lr_backend la_frame_backend(lua_State *L, int idx, const char *fn, const char *file)
{
    const char *name = la_opt_string(L, idx, fn, "backend", NULL);
    if (!name && file && lr_format_of(file) != LR_FORMAT_PNG)
        return LR_BACKEND_CAIRO;
    const lamina_run *run = la_run(L);
    if (!name)
        name = run && run->backend ? run->backend : "cairo";
    lr_backend b;
    char why[512];
    if (lr_backend_parse(name, &b, why, sizeof why) != 0)
        luaL_error(L, "%s: %s", fn, why);
    if (lr_backend_check(b, why, sizeof why) != 0)
        luaL_error(L, "%s: backend = \"%s\": %s", fn, name, why);
    return b;
}

/* panels = { {...}, ... }: each panel's table; the frame's own panel keys
 * are their defaults. Returns the count. */
static size_t panels(lua_State *L, la_frame_ctx *ctx, lr_panel **out)
{
    static const char *const panel_keys[] = { "sim", "title", LA_PANEL_KEYS, NULL };
    if (la_getfield(L, 2, "panels") == LUA_TNIL) {
        lua_pop(L, 1);
        *out = la_frame_scratch(L, ctx, sizeof **out);
        la_frame_panel(L, ctx, 2, 0, 1, *out);
        return 1;
    }
    int idx = lua_gettop(L);
    size_t n = la_frame_panel_count(L, idx, ctx->fn);   /* l_frame_common.c */
    *out = la_frame_scratch(L, ctx, n * sizeof **out);
    for (size_t i = 0; i < n; i++) {
        char name[48];
        la_frame_panel_at(L, idx, i, ctx->fn, panel_keys, name);
        la_frame_panel(L, ctx, 2, lua_gettop(L), 1, &(*out)[i]);
        lua_pop(L, 1);
    }
    lua_pop(L, 1);
    return n;
}

/* scale = k: every point drawn at X0 + k (x - X0), X0 its reference
 * position (l_ref.c); a finite number > 0, 1 by default. */
static double scale_opt(lua_State *L, const char *fn)
{
    int t = la_getfield(L, 2, "scale");
    double k = 1;
    if (t != LUA_TNIL) {
        if (t != LUA_TNUMBER)
            luaL_error(L, "%s: 'scale' must be a number > 0 (got %s)", fn,
                       luaL_typename(L, -1));
        k = lua_tonumber(L, -1);
        if (!(k > 0) || !isfinite(k))
            luaL_error(L, "%s: 'scale' must be a finite number > 0 (got %f)", fn, k);
    }
    lua_pop(L, 1);
    return k;
}

/* layout = {rows, cols} */
static void layout(lua_State *L, const char *fn, size_t n, lr_figure *f)
{
    if (la_getfield(L, 2, "layout") != LUA_TNIL) {
        double r = 0, c = 0;
        if (lua_istable(L, -1) && lua_rawlen(L, -1) == 2) {
            lua_rawgeti(L, -1, 1);
            lua_rawgeti(L, -2, 2);
            r = lua_tonumber(L, -2);
            c = lua_tonumber(L, -1);
            lua_pop(L, 2);
        }
        la_frame_layout(L, fn, r, c, n, &f->rows, &f->cols);
    }
    lua_pop(L, 1);
}

/* A frame's `label` key (issue 31 item 7), 2D and 3D alike: a string, or
 * true / absent for the clock "t = ...   step ...", false for none. What it
 * pushes stays on the stack until the frame is written. */
const char *la_frame_label(lua_State *L, int idx, const char *fn, double t, long step)
{
    int lt = la_getfield(L, idx, "label");
    if (lt != LUA_TNIL && lt != LUA_TSTRING && lt != LUA_TBOOLEAN)
        luaL_error(L, "%s: 'label' must be a string, true or false (got %s)", fn,
                   luaL_typename(L, -1));
    if (lt == LUA_TSTRING) return lua_tostring(L, -1);
    if (lt == LUA_TNIL || lua_toboolean(L, -1)) {
        char text[64];
        snprintf(text, sizeof text, "t = %.4f   step %ld", t, step);
        return lua_pushstring(L, text);
    }
    return NULL;
}

/* A panel's colour bar's ends, for lamina:range (0: it has none). */
static int panel_range(const void *panels, size_t k, double *lo, double *hi)
{
    const lr_panel *p = (const lr_panel *)panels + k;
    if (!p->colourbar) return 0;
    lr_panel_value_range(p, lo, hi);
    return 1;
}

int la_sim_frame(lua_State *L)
{
    static const char *const keys[] = { "file", "width", "height", "title", "label",
                                        "backend", "layout", "panels", "scale",
                                        LA_PANEL_KEYS,
                                        NULL };
    const char *fn = "sim:frame";
    la_sim *s = la_check_sim(L, 1);
    la_check_keys(L, 2, fn, keys);
    const lm_sim *sim = s->sim;
    const char *file = la_opt_output_path(L, 2, fn, "file");
    if (!file) return luaL_error(L, "%s: 'file' is required", fn);
    lr_figure f;
    memset(&f, 0, sizeof f);
    la_frame_size(L, 2, fn, &f.width, &f.height);
    f.backend = la_frame_backend(L, 2, fn, file);
    la_frame_ctx ctx = { fn, 0, 0, 0, 0, 0, 0, scale_opt(L, fn) };
    lua_newtable(L);
    ctx.anchor = lua_gettop(L);
    lr_panel *p = NULL;
    f.npanels = panels(L, &ctx, &p);
    f.panels = p;
    layout(L, fn, f.npanels, &f);
    f.title = la_opt_string(L, 2, fn, "title", NULL);
    if (ctx.scale != 1) {   /* the title says the drawing is exaggerated */
        char t[64];
        snprintf(t, sizeof t, "displacements x %g", ctx.scale);
        f.title = f.title && *f.title ? lua_pushfstring(L, "%s - %s", f.title, t)
                                      : lua_pushstring(L, t);
    }
    f.label = la_frame_label(L, 2, fn, sim->t, sim->step);
    /* label and title strings stay on the stack until we return */

    /* lamina:layers: what the frame shows of its membranes, so that a
     * check can read it from the file (tests/visual/check_membrane_frames.py) */
    char layers[96];
    snprintf(layers, sizeof layers, "membranes=%d with_phi=%d phi=%d normals=%d", ctx.membranes,
             ctx.with_phi, ctx.phi, ctx.normals);
    /* the title as text too: what a frame says it shows - "displacements
     * x k" - can be read back by a check */
    la_frame_texts tx;
    f.ntext = la_frame_text(L, &tx, layers, f.title, (la_frame_ranges){p, f.npanels, panel_range});
    f.text = tx.text;
    char err[512];
    return la_frame_written(L, fn, file, lr_figure_write(&f, file, err, sizeof err), err);
}
