/* fuzz_lua.c - libFuzzer target: the Lua API. The bytes choose statements
 * from a small grammar of lamina's constructors and methods and the values
 * of their arguments (odd ones on purpose: NaN, 1e308, "../x.png", "a\0b",
 * tables with metatables, objects of the wrong kind); the script runs in
 * the sandbox of `lamina run`, each statement in a pcall, so that one
 * error does not end the input. A run is capped at 50 steps, the Lua state
 * at 64 MB, the process (Lua, engine and canvases: src/util/lu_budget.c) at
 * 128 MB, the script at 20 million instructions. Any crash, sanitizer
 * report or leak is a finding. The process cap keeps an input's work
 * bounded: without it a 1000 x 1000 grid filled with 9 million gas points
 * (a disk of radius 17 clipped to the domain, ppc 9), drawn in six frames,
 * is a legitimate 2.5 GB run that passed libFuzzer's 20 s per input, a
 * timeout that says nothing about crashes. */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <lauxlib.h>
#include <lua.h>

#include "lamina_lua.h"
#include "fuzz_target.h"
#include "util.h"

static const char *const statements[] = {
    "S = lamina.sim{dt = %s, domain = %s, cell = %s, gravity = %s}",
    "S = lamina.sim{dt = %s, boundary = %s, scheme = %s, courant = %s}",
    "M = lamina.elastic{rho = %s, E = %s, nu = %s}",
    "M = lamina.gas{rho = %s, e = %s, split = %s, density = %s}",
    "M = lamina.membrane{rho = %s, E = %s, thickness = %s}",
    "M = lamina.linear_fluid{rho = %s, beta = %s}",
    "R = lamina.disk{center = %s, radius = %s}",
    "R = lamina.rect{min = %s, max = %s}",
    "R = lamina.polygon{points = %s}",
    "B = S:body{material = M, region = R, ppc = %s, velocity = %s}",
    "B = S:body{material = %s, region = %s, fill = %s}",
    "S:membrane{material = M, curve = lamina.segment{from = %s, to = %s}, spacing = %s}",
    "S:membrane{material = M, curve = lamina.arc{center = %s, radius = %s, from = 0, to = 90}, count = %s}",
    "Q = S:record{every = %s, energy = %s, values = %s, points = %s}",
    "Q = S:record{file = %s, angle = %s, average = %s}",
    "S:every(%s, function(s) X = s.t end)",
    "S:at(%s, %s)",
    "S:run{t_end = %s}",
    "S:step(%s)",
    "S:frame{file = %s, width = %s, height = %s}",
    "S:frame{file = 'out/fuzz/f.png', width = 32, height = 32, colour = %s, range = %s}",
    "S:frame{file = 'out/fuzz/p.png', width = 32, height = 32, panels = %s, layout = %s}",
    "S:frame{file = 'out/fuzz/s.png', width = 32, height = 32, split = %s, mirror = %s}",
    "lamina.plot{file = %s, series = %s, csv = %s}",
    "S.dt = %s",
    "S.gravity = %s",
    "M.E = %s",
    "X = Q:column(%s)",
    "X = Q:mean(%s, %s, %s)",
    "X = B:com()",
    "X = lamina.normals{points = %s, box = %s, cells = %s}",
    "F = lamina.figure{width = %s, height = %s}",
    "F:write(%s)",
    "X = getmetatable(%s)",
    "setmetatable(%s, {})",
    "X = %s.t",
    "X = tostring(%s)",
    "X = require(%s)",
    "X = load(tostring(%s), 'x', %s)",   /* (a reader function can feed load for ever) */
    "X = lamina.param(%s, %s)",
    "collectgarbage(%s)",
};

static const char *const values[] = {
    "0", "1", "-1", "0.5", "0.05", "0.25", "2", "4", "9", "17", "100", "1e-3", "1e308",
    "-1e308", "1e-300", "5e-324", "0/0", "1/0", "-1/0", "1e12", "2^53", "1e-12", "5000",
    "'x'", "'out/fuzz/a.png'", "'out/fuzz/a.svg'", "'out/fuzz/a.pdf'", "'out/fuzz/r.csv'",
    "'../x.png'", "'a\\0b.png'", "'/dev/null'", "'out/fuzz/a\\nb.png'", "'speed'",
    "'body'", "'pressure'", "'free'", "'usl'", "'cell'", "'stop'", "'dogbone'", "'../../x'",
    "{}", "{0, 0}", "{1, 1}", "{0.5, 0.5}", "{1, 0}", "{0, 0, 1, 1}", "{0, 0, 0, 1, 1, 1}",
    "{{0, 0}, {1, 0}, {0, 1}}", "{{0.2, 0.2}, {0.8, 0.2}, {0.5, 0.9}, {0.2, 0.8}}",
    "{0.1, 0.01}", "{1, 0/0}", "{2, 2}", "{3, 3, 3}", "{left = 'free', top = 'symmetry'}",
    "true", "false", "nil", "S", "M", "R", "B", "Q", "F", "X",
    "function() return 1 end", "function(s) return s.t end", "function() error('e') end",
    "setmetatable({}, {__index = function(_, k) return 'out/fuzz/' .. k end})",
    "{x = {0, 1}, y = {0, 1}}", "{{x = {0, 1}, y = {1, 2}, label = 'a'}}",
    "{{x = {}, y = {}}}", "{a = function() return 1 end}", "{p = {B, 1}}", "{p = {B, -1}}",
    "{a = B}", "string.rep('x', 100)", "{S}", "{{sim = S}, {sim = S}}", "{S, S}",
    "string.char(27) .. 'Lua'", "{[1] = 1, x = 2}",
};

#define NS (sizeof statements / sizeof *statements)
#define NV (sizeof values / sizeof *values)

typedef struct gen {
    const uint8_t *p, *end;
} gen;

static unsigned next(gen *g)
{
    return g->p < g->end ? *g->p++ : 0;
}

/* The script the bytes choose: at most 32 statements, each in a pcall. */
static char *script(const uint8_t *data, size_t size)
{
    gen g = {data, data + size};
    size_t cap = 65536, len = 0;
    char *out = malloc(cap);
    if (!out) return NULL;
    len += (size_t)snprintf(out, cap, "local pcall = pcall\n");
    for (int k = 0; k < 32 && g.p < g.end; k++) {
        const char *st = statements[next(&g) % NS];
        const char *v[4];
        for (int i = 0; i < 4; i++) v[i] = values[next(&g) % NV];
        char line[2048];
        snprintf(line, sizeof line, st, v[0], v[1], v[2], v[3]);
        len += (size_t)snprintf(out + len, cap - len, "pcall(function() %s end)\n", line);
        if (len > cap - 4096) break;
    }
    return out;
}

/* A script may loop by itself (a reader function given to load, say); that
 * is no finding: after 20 million instructions it is stopped. */
static void budget(lua_State *L, lua_Debug *ar)
{
    (void)ar;
    lua_sethook(L, budget, LUA_MASKCOUNT, 1);   /* and at every instruction after */
    luaL_error(L, "fuzz: instruction budget spent");
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char *code = script(data, size);
    if (!code) return 0;
    lamina_run run;
    memset(&run, 0, sizeof run);
    run.script = "fuzz.lua";
    run.quiet = 1;
    run.max_steps = 50;                 /* runs stop at 50 steps */
    run.lua_mem_limit = (size_t)64 << 20;
    lu_budget_set_limit((size_t)128 << 20);
    lua_State *L = lamina_open_state(&run);
    if (L) {
        lua_sethook(L, budget, LUA_MASKCOUNT, 20000000);
        if (luaL_loadbufferx(L, code, strlen(code), "=fuzz", "t") == LUA_OK)
            lua_pcall(L, 0, 0, 0);
        lua_close(L);
    }
    free(code);
    return 0;
}
