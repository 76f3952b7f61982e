/* fuzz_csv.c - libFuzzer target: lamina.read_csv on arbitrary bytes (a
 * CSV a script reads back, e.g. another run's records in a sweep), in the
 * sandbox of `lamina run`. The file is written under the working
 * directory, where the reader's path check admits it. Either the call
 * fails with a message, or it returns equal-length number columns, one per
 * header name: anything else, a crash or a sanitizer report is a finding. */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <lauxlib.h>
#include <lua.h>

#include "lamina_lua.h"
#include "fuzz_target.h"

static const char *const check =
    "local h, names, n = lamina.read_csv('fuzz-input.csv')\n"
    "assert(math.type(n) == 'integer' and n >= 0 and #names >= 1)\n"
    "for _, k in ipairs(names) do\n"
    "  local c = h[k]\n"
    "  assert(type(c) == 'table' and #c == n, 'column ' .. k)\n"
    "  for i = 1, n do assert(type(c[i]) == 'number') end\n"
    "end\n";

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    FILE *f = fopen("fuzz-input.csv", "wb");
    if (!f) abort();
    if (size && fwrite(data, 1, size, f) != size) abort();
    fclose(f);
    lamina_run run;
    memset(&run, 0, sizeof run);
    run.script = "fuzz.lua";
    run.quiet = 1;
    run.lua_mem_limit = (size_t)64 << 20;
    lua_State *L = lamina_open_state(&run);
    if (!L) abort();
    if (luaL_loadbufferx(L, check, strlen(check), "=fuzz", "t") != LUA_OK) abort();
    if (lua_pcall(L, 0, 0, 0) != LUA_OK) {
        /* a refusal is fine; a failed consistency check is a finding */
        const char *msg = lua_tostring(L, -1);
        if (!msg || !strstr(msg, "lamina.read_csv")) {
            fprintf(stderr, "fuzz_csv: %s\n", msg ? msg : "(no message)");
            abort();
        }
    }
    lua_close(L);
    return 0;
}
