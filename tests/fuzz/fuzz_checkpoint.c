/* fuzz_checkpoint.c - libFuzzer target: `lamina run --restart` on arbitrary
 * bytes (issue 31 item 3: a checkpoint is untrusted input; 16 of 343 mutated
 * ones crashed the release build). The scene is tests/security/scripts/
 * ck_scene.lua's (an elastic disk, a pinned membrane with a link, splitting
 * gas, a recorder), so corpus/checkpoint/good.ck - written by that script -
 * restores. Either the restart is refused with a message, or the run goes on
 * (it may then fail as a simulation): a crash, a hang or a sanitizer report
 * is a finding. Under ASan + UBSan (LAMINA_FUZZ=ON) the few steps after a
 * restore read every index the checkpoint gave. */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <lauxlib.h>
#include <lua.h>

#include "lamina_lua.h"
#include "fuzz_target.h"

static const char *const scene =
    "local sim = lamina.sim{ dt = 5e-4, domain = {0, 0, 1, 1}, cell = 0.1 }\n"
    "local el = lamina.elastic{ rho = 1000, E = 1e4, nu = 0.3 }\n"
    "local mm = lamina.membrane{ rho = 1000, E = 1e4, nu = 0.3, thickness = 0.01 }\n"
    "local gas = lamina.gas{ rho = 1, gamma = 1.4, e = 10, split = 60 }\n"
    "local disk = sim:body{ material = el, region = lamina.disk{ center = {0.3, 0.6}, radius = 0.12 } }\n"
    "local sheet = sim:membrane{ material = mm, curve = lamina.segment{ from = {0.1, 0.2}, to = {0.9, 0.2} },\n"
    "                            spacing = 0.05 }\n"
    "sheet:pin{ points = 'ends' }\n"
    "sim:link{ a = {disk, 1}, b = {sheet, 5}, stiffness = 10 }\n"
    "sim:body{ material = gas, region = lamina.rect{ min = {0.6, 0.5}, max = {0.9, 0.8} } }\n"
    "sim:record{ energy = true }\n"
    "sim:run{ t_end = 0.003 }\n";

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    FILE *f = fopen("fuzz-input.ck", "wb");
    if (!f) abort();
    if (size && fwrite(data, 1, size, f) != size) abort();
    fclose(f);
    lamina_run run;
    memset(&run, 0, sizeof run);
    run.script = "fuzz.lua";
    run.quiet = 1;
    run.restart = "fuzz-input.ck";
    run.lua_mem_limit = (size_t)256 << 20;
    lua_State *L = lamina_open_state(&run);
    if (!L) abort();
    if (luaL_loadbufferx(L, scene, strlen(scene), "=fuzz", "t") != LUA_OK) abort();
    if (lua_pcall(L, 0, 0, 0) != LUA_OK) {
        /* a refusal or a failed simulation is fine; anything else (a
         * mistake in the scene above) is not. A restored state that is in
         * range but too fast for the step (a gas energy of 1e304: finite,
         * positive) is refused by the Courant check naming the body and its
         * c_max, which is a refusal too (found by this target, 2026-12-03). */
        const char *msg = lua_tostring(L, -1);
        if (!msg || (!strstr(msg, "--restart") && !strstr(msg, "simulation failed") &&
                     !strstr(msg, "is too large: Courant number"))) {
            fprintf(stderr, "fuzz_checkpoint: %s\n", msg ? msg : "(no message)");
            abort();
        }
    }
    lua_close(L);
    return 0;
}
