/* test_frame3d_lua.c - the Lua entry of 3D frames, l_frame3d
 * (src/lua/l_frame3d.h), on an lm3_sim built through mpm3.h, until
 * lamina.sim{dim = 3} lands and sim:frame calls it: a C function holding
 * the sim is given to a Lua chunk as `frame`.
 *
 *   - a frame coloured by pressure with a pressure slice, a density
 *     isosurface and two panels is written; its PNG's lamina:range is the
 *     particles' pressure range computed here, -(sxx + syy + szz) / 3;
 *     lamina:layers counts what was drawn;
 *   - the same call twice writes the same pixels (every backend here);
 *   - bad keys and values are refused by name: an unknown key, an unknown
 *     field, a slice outside the domain, a fov of 130, an SVG file, an
 *     isosurface without a level. */
#include <lauxlib.h>
#include <lua.h>
#include <lualib.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "check.h"
#include "l_frame3d.h"
#include "mpm3.h"
#include "render.h"

static lm3_sim *sim;

static int frame(lua_State *L)
{
    return l_frame3d(L, sim, 1);
}

static lm3_sim *make_sim(double *pmin, double *pmax)
{
    lm3_def d;
    memset(&d, 0, sizeof d);
    for (int a = 0; a < 3; a++)
        d.hi[a] = 1;
    d.cell = 0.05;
    d.dt = 1e-4;
    d.basis = LM_BASIS_LINEAR;
    char err[256];
    lm3_sim *s = lm3_sim_create(&d, err, sizeof err);
    CHECK(s != NULL);
    lm3_material m = {.rho = 1000, .E = 1e6, .nu = 0.3, .kind = LM3_ELASTIC};
    int k = lm3_material_add(s, &m, err, sizeof err);
    const double lo[3] = {0.2, 0.2, 0.1}, hi[3] = {0.8, 0.8, 0.5}, v[3] = {0, 0, 0};
    CHECK(lm3_seed_box(s, k, lo, hi, 2, v) > 0);
    const double lo2[3] = {0.35, 0.35, 0.6}, hi2[3] = {0.65, 0.65, 0.9};
    int k2 = lm3_material_add(s, &m, err, sizeof err);
    CHECK(lm3_seed_box(s, k2, lo2, hi2, 2, v) > 0);
    /* a hydrostatic-like stress: pressure falling with height, a shear
     * that varies in x */
    *pmin = INFINITY;
    *pmax = -INFINITY;
    for (size_t i = 0; i < s->p.n; i++) {
        double z = s->p.x[2][i], x = s->p.x[0][i];
        double p = 1e4 * (1 - z) + 500 * sin(6 * x);
        s->p.s[0][i] = -p + 100;
        s->p.s[1][i] = -p - 100;
        s->p.s[2][i] = -p;
        s->p.s[5][i] = 50 * x;
        double mean = -(s->p.s[0][i] + s->p.s[1][i] + s->p.s[2][i]) / 3.0;
        *pmin = fmin(*pmin, mean);
        *pmax = fmax(*pmax, mean);
        s->p.v[2][i] = -x;
    }
    return s;
}

/* Runs chunk with `frame` defined; returns the error message (static) or
 * NULL. */
static const char *run(lua_State *L, const char *chunk)
{
    static char msg[1024];
    lua_pushcfunction(L, frame);
    lua_setglobal(L, "frame");
    if (luaL_dostring(L, chunk) != 0) {
        snprintf(msg, sizeof msg, "%s", lua_tostring(L, -1));
        lua_pop(L, 1);
        return msg;
    }
    return NULL;
}

/* The tEXt chunk key of a PNG, found in its bytes. */
static int png_text(const char *path, const char *key, char *out, size_t n)
{
    FILE *f = fopen(path, "rb");
    if (!f)
        return -1;
    static unsigned char buf[1 << 22];
    size_t len = fread(buf, 1, sizeof buf, f);
    fclose(f);
    size_t kl = strlen(key);
    for (size_t i = 8; i + 8 + kl < len; i++)
        if (memcmp(buf + i, "tEXt", 4) == 0 && memcmp(buf + i + 4, key, kl) == 0 &&
            buf[i + 4 + kl] == 0) {
            size_t clen = ((size_t)buf[i - 4] << 24) | ((size_t)buf[i - 3] << 16) |
                          ((size_t)buf[i - 2] << 8) | buf[i - 1];
            size_t vl = clen - kl - 1;
            if (vl >= n)
                vl = n - 1;
            memcpy(out, buf + i + 5 + kl, vl);
            out[vl] = 0;
            return 0;
        }
    return -1;
}

static unsigned char *pixels(const char *path, int *w, int *h)
{
    unsigned char *rgba = NULL;
    char err[256];
    if (lr_png_read(path, w, h, &rgba, err, sizeof err) != 0) {
        fprintf(stderr, "%s\n", err);
        return NULL;
    }
    return rgba;
}

static void test_frames(lua_State *L, const char *backend, double pmin, double pmax)
{
    char chunk[2048], a[64], b[64];
    snprintf(a, sizeof a, "out/frame3d_lua_%s.png", backend);
    snprintf(b, sizeof b, "out/frame3d_lua_%s_again.png", backend);
    const char *body =
        "for _, f in ipairs{'%s', '%s'} do\n"
        "  frame{ file = f, width = 960, height = 480, backend = '%s', title = 'a 3D frame',\n"
        "         colour = 'pressure', layout = {1, 2},\n"
        "         panels = { { title = 'pressure; density = 500 isosurface',\n"
        "                      isosurface = {field = 'mass', level = 500} },\n"
        "                    { title = 'slice y = 0.5 (pressure), perspective', fov = 35,\n"
        "                      azimuth = -40, colour = 'body', particles = false,\n"
        "                      slice = {axis = 'y', at = 0.5, field = 'pressure'} } } }\n"
        "end\n";
    snprintf(chunk, sizeof chunk, body, a, b, backend);
    const char *err = run(L, chunk);
    if (err)
        fprintf(stderr, "%s: %s\n", backend, err);
    CHECK(err == NULL);
    char text[256] = "";
    CHECK(png_text(a, "lamina:range", text, sizeof text) == 0);
    double lo = NAN, hi = NAN;
    CHECK(sscanf(text, "%lf %lf", &lo, &hi) == 2);
    printf("%s: lamina:range %s; pressure of the particles %.17g .. %.17g\n", backend, text,
           pmin, pmax);
    CHECK(lo == pmin && hi == pmax);
    CHECK(png_text(a, "lamina:layers", text, sizeof text) == 0);
    CHECK(strstr(text, "slices=1 isosurfaces=1") != NULL);
    int w1, h1, w2, h2;
    unsigned char *p1 = pixels(a, &w1, &h1), *p2 = pixels(b, &w2, &h2);
    CHECK(p1 && p2 && w1 == 960 && h1 == 480 && w2 == w1 && h2 == h1);
    if (p1 && p2)
        CHECK(memcmp(p1, p2, 4 * (size_t)w1 * h1) == 0);
    free(p1);
    free(p2);
}

static void refused(lua_State *L, const char *chunk, const char *want)
{
    const char *err = run(L, chunk);
    if (!err || !strstr(err, want))
        fprintf(stderr, "expected an error with \"%s\", got: %s\n", want, err ? err : "none");
    CHECK(err && strstr(err, want));
}

int main(void)
{
    double pmin, pmax;
    sim = make_sim(&pmin, &pmax);
    mkdir("out", 0777);
    lua_State *L = luaL_newstate();
    luaL_openlibs(L);
    for (int bk = 0; bk < LR_BACKEND_COUNT; bk++) {
        char why[256];
        if (lr_backend_check((lr_backend)bk, why, sizeof why) != 0)
            continue;
        test_frames(L, lr_backend_name((lr_backend)bk), pmin, pmax);
    }
    refused(L, "frame{file = 'out/x.png', colr = 'speed'}", "unknown key 'colr'");
    refused(L, "frame{file = 'out/x.png', colour = 'sped'}", "colour = \"sped\": unknown field");
    refused(L, "frame{file = 'out/x.png', slice = {axis = 'z', at = 1.5}}",
            "at = 1.5 is outside the domain's z range");
    refused(L, "frame{file = 'out/x.png', fov = 130}", "'fov' must be in (0, 120)");
    refused(L, "frame{file = 'out/x.svg'}", "a 3D frame is written as PNG");
    refused(L, "frame{file = 'out/x.png', isosurface = {field = 'rho'}}", "'level' is required");
    refused(L, "frame{file = 'out/x.png', panels = {{windw = 1}}}",
            "panels[1]: unknown key 'windw'");
    refused(L, "frame{file = 'out/x.png', target = {1, 2}}", "'target' must be a list of 3");
    lua_close(L);
    lm3_sim_free(sim);
    lr_shutdown();
    return CHECK_DONE();
}
