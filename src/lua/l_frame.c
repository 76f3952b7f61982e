/* l_frame.c - sim:frame{...}: the simulation's state drawn to a PNG.
 *
 * The binding only gathers what render.h's lr_frame asks for; the drawing is
 * src/render's. Every PNG carries provenance (design.md, Rendering). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "l_internal.h"
#include "render.h"

/* Particle radius in world units: half the smallest particle spacing, from
 * the volume a particle started with. */
static double particle_radius(const lm_sim *sim)
{
    double r = 0;
    for (int b = 0; b < sim->nbodies; b++) {
        const lm_body *bd = &sim->bodies[b];
        if (bd->count == 0) continue;
        size_t q = bd->first;
        double v = sim->p.m[q] / sim->mats[bd->mat]->rho;
        double rb = 0.5 * sqrt(v);
        if (r == 0 || rb < r) r = rb;
    }
    return r;
}

/* The --set parameters as one line, "name=value name=value". */
static const char *set_line(lua_State *L, const lamina_run *run)
{
    luaL_Buffer b;
    luaL_buffinit(L, &b);
    for (int i = 0; run && i < run->nsets; i++) {
        if (i) luaL_addchar(&b, ' ');
        luaL_addstring(&b, run->sets[i].name);
        luaL_addchar(&b, '=');
        luaL_addstring(&b, run->sets[i].value);
    }
    luaL_pushresult(&b);
    return lua_tostring(L, -1);
}

static void remember_dir(lamina_run *run, const char *path)
{
    const char *slash = strrchr(path, '/');
    size_t n = slash ? (size_t)(slash - path) + 1 : 0;
    if (n >= sizeof run->frame_dir) n = sizeof run->frame_dir - 1;
    memcpy(run->frame_dir, path, n);
    run->frame_dir[n] = 0;
    if (n == 0) strcpy(run->frame_dir, "./");
}

int la_sim_frame(lua_State *L)
{
    static const char *const keys[] = {"file", "width", "height", "title", "grid",
                                       "window", "label", NULL};
    const char *fn = "sim:frame";
    la_sim *s = la_check_sim(L, 1);
    la_check_keys(L, 2, fn, keys);
    const lm_sim *sim = s->sim;
    const lm_grid *g = &sim->grid;
    const char *file = la_opt_string(L, 2, fn, "file", NULL);
    if (!file) return luaL_error(L, "%s: 'file' is required", fn);
    double w = la_opt_number(L, 2, fn, "width", 800);
    double h = la_opt_number(L, 2, fn, "height", 800);
    if (!(w >= 16 && w <= 16384) || !(h >= 16 && h <= 16384) || w != (int)w || h != (int)h)
        return luaL_error(L, "%s: width and height must be whole numbers in [16, 16384] "
                          "(got %f x %f)", fn, w, h);

    lr_frame f;
    memset(&f, 0, sizeof f);
    f.width = (int)w;
    f.height = (int)h;
    f.wx0 = g->x0;
    f.wy0 = g->y0;
    f.wx1 = g->x0 + g->nx * g->hx;
    f.wy1 = g->y0 + g->ny * g->hy;
    if (la_has(L, 2, "window")) {
        lua_getfield(L, 2, "window");
        if (!lua_istable(L, -1) || lua_rawlen(L, -1) != 4)
            return luaL_error(L, "%s: 'window' must be {x0, y0, x1, y1}", fn);
        double v[4];
        for (int i = 0; i < 4; i++) {
            lua_rawgeti(L, -1, i + 1);
            v[i] = luaL_checknumber(L, -1);
            lua_pop(L, 1);
        }
        lua_pop(L, 1);
        if (!(v[2] > v[0]) || !(v[3] > v[1]))
            return luaL_error(L, "%s: 'window' is empty", fn);
        f.wx0 = v[0]; f.wy0 = v[1]; f.wx1 = v[2]; f.wy1 = v[3];
    }
    lr_grid grid = {g->x0, g->y0, g->hx, g->hy, g->nx, g->ny};
    lua_getfield(L, 2, "grid");
    f.grid = (lua_isnil(L, -1) || lua_toboolean(L, -1)) ? &grid : NULL;
    lua_pop(L, 1);
    f.n = sim->p.n;
    f.x = sim->p.x;
    f.y = sim->p.y;
    f.group = sim->p.body;
    f.radius = particle_radius(sim);
    f.title = la_opt_string(L, 2, fn, "title", NULL);
    lua_getfield(L, 2, "label");
    if (lua_isstring(L, -1)) f.label = lua_tostring(L, -1);
    else if (lua_isnil(L, -1) || lua_toboolean(L, -1)) {
        char t[64];
        snprintf(t, sizeof t, "t = %.4f   step %ld", sim->t, sim->step);
        f.label = lua_pushstring(L, t);
    }
    /* label and title strings stay on the stack until we return */

    lamina_run *run = la_run(L);
    char ver[64], hash[32];
    snprintf(ver, sizeof ver, "lamina %s", LAMINA_VERSION);
    snprintf(hash, sizeof hash, "%s", run ? run->script_hash : "");
    lr_text_chunk text[4] = {{"Software", ver},
                             {"lamina:script", run && run->script ? run->script : ""},
                             {"lamina:script-hash", hash},
                             {"lamina:set", set_line(L, run)}};
    f.text = text;
    f.ntext = 4;
    char err[512];
    if (lr_frame_write(&f, file, err, sizeof err))
        return luaL_error(L, "%s: %s", fn, err);
    if (run) {
        run->frames++;
        remember_dir(run, file);
    }
    lua_pushstring(L, file);
    return 1;
}
