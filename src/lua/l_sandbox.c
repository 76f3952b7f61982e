/* l_sandbox.c - what a scenario script may use of Lua's standard library.
 *
 * A script is untrusted input (docs/design.md): people run scripts they
 * downloaded. So a script gets the pure libraries (base, coroutine, table,
 * string, math, utf8), a few harmless functions of io and os, and nothing
 * that reaches a file, a process or a shared library except through
 * lamina's API:
 *   - no `package` library (no loadlib, no cpath, no path to rewrite);
 *     `require` is lamina's own and reads only the read folders below;
 *   - `load` takes text only; `loadfile` and `dofile` take text files in the
 *     read folders only; `string.dump` is gone (no binary chunks at all:
 *     liblua does not verify bytecode, and a mutated chunk crashes it);
 *   - `setmetatable` refuses `__gc`: no script code runs from inside the
 *     collector, so nothing can change a table while a binding reads it;
 *   - `collectgarbage` keeps the options that cannot stop the collector.
 * The read folders are lamina's Lua library (assets/lua), lamina's own
 * scripts (scripts/) and the script's folder, each with its subfolders,
 * after symbolic links are resolved. */
#define _XOPEN_SOURCE 700     /* realpath */
#include <errno.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include <lualib.h>

#include "l_internal.h"

#define READ_ROOTS "lamina.read_roots"   /* registry: folders dofile reads */
#define REQUIRE_ROOTS "lamina.require_roots" /* registry: folders require reads */
#define MODULES "lamina.modules"         /* registry: require's cache */
#define SCRIPT_FOLDER "lamina.script_folder" /* registry: the script's real folder */
#define MAX_MODULE_NAME 128

int lamina_check_script_file(const char *path, char *err, size_t len)
{
    struct stat st;
    if (stat(path, &st) != 0) {
        snprintf(err, len, "cannot read script '%s': %s", path, strerror(errno));
        return -1;
    }
    if (!S_ISREG(st.st_mode)) {   /* /dev/zero, a FIFO: reading would not end */
        snprintf(err, len, "cannot read script '%s': not a regular file", path);
        return -1;
    }
    return 0;
}

int la_load_script(lua_State *L, const char *path)
{
    char err[PATH_MAX + 64];
    if (lamina_check_script_file(path, err, sizeof err) != 0) {
        lua_pushstring(L, err);
        return LUA_ERRFILE;
    }
    return luaL_loadfilex(L, path, "t");
}

/* ---- read folders ---------------------------------------------------- */

static void add_root(lua_State *L, int list, const char *dir)
{
    char real[PATH_MAX];
    if (!realpath(dir, real)) return;   /* a missing folder holds nothing */
    lua_pushstring(L, real);
    lua_rawseti(L, list, (lua_Integer)lua_rawlen(L, list) + 1);
}

/* require: assets/lua, then the script's folder; dofile and loadfile also
 * lamina's scripts/ (a test scene runs an example as it is). */
static void set_read_roots(lua_State *L, const char *script)
{
    const char *assets = getenv("LAMINA_ASSETS");
    if (!assets || !*assets) assets = LAMINA_ASSETS_DIR;
    lua_newtable(L);
    int list = lua_gettop(L);
    lua_pushfstring(L, "%s/lua", assets);
    add_root(L, list, lua_tostring(L, -1));
    lua_pop(L, 1);
    const char *slash = script ? strrchr(script, '/') : NULL;
    if (slash) {
        lua_pushlstring(L, script, slash == script ? 1 : (size_t)(slash - script));
        add_root(L, list, lua_tostring(L, -1));
        lua_pop(L, 1);
    } else {
        add_root(L, list, ".");
    }
    {   /* the script's folder alone, for the files that come with it (a
         * mesh: la_check_asset_path) */
        char real[PATH_MAX];
        if (slash) lua_pushlstring(L, script, slash == script ? 1 : (size_t)(slash - script));
        else lua_pushliteral(L, ".");
        if (realpath(lua_tostring(L, -1), real)) {
            lua_pushstring(L, real);
            lua_setfield(L, LUA_REGISTRYINDEX, SCRIPT_FOLDER);
        }
        lua_pop(L, 1);
    }
    lua_pushvalue(L, list);
    lua_setfield(L, LUA_REGISTRYINDEX, REQUIRE_ROOTS);
    lua_newtable(L);   /* the read roots: a copy plus scripts/ */
    for (lua_Integer i = 1; i <= (lua_Integer)lua_rawlen(L, list); i++) {
        lua_rawgeti(L, list, i);
        lua_rawseti(L, -2, i);
    }
    lua_pushfstring(L, "%s/../scripts", assets);
    add_root(L, list + 1, lua_tostring(L, -1));
    lua_pop(L, 1);
    lua_setfield(L, LUA_REGISTRYINDEX, READ_ROOTS);
    lua_pop(L, 1);
}

int la_script_folder(lua_State *L, char *out, size_t len)
{
    int ok = lua_getfield(L, LUA_REGISTRYINDEX, SCRIPT_FOLDER) == LUA_TSTRING;
    if (ok) snprintf(out, len, "%s", lua_tostring(L, -1));
    lua_pop(L, 1);
    return ok;
}

static int under(const char *path, const char *root)
{
    size_t n = strlen(root);
    if (strncmp(path, root, n) != 0) return 0;
    return path[n] == '/' || path[n] == '\0' || (n == 1 && root[0] == '/');
}

/* 1 when path is a regular file inside one of the read folders. */
static int readable(lua_State *L, const char *path)
{
    char real[PATH_MAX];
    struct stat st;
    if (!realpath(path, real) || stat(real, &st) != 0 || !S_ISREG(st.st_mode)) return 0;
    lua_getfield(L, LUA_REGISTRYINDEX, READ_ROOTS);
    int ok = 0;
    lua_Integer n = (lua_Integer)lua_rawlen(L, -1);
    for (lua_Integer i = 1; i <= n && !ok; i++) {
        lua_rawgeti(L, -1, i);
        ok = under(real, lua_tostring(L, -1));
        lua_pop(L, 1);
    }
    lua_pop(L, 1);
    return ok;
}

/* Pushes the text chunk of a file in the read folders (LUA_OK) or an error
 * message; never says what the file holds unless it is one of those (a
 * syntax error quotes the source). */
static int load_confined(lua_State *L, const char *fn, const char *path)
{
    if (strlen(path) != lua_rawlen(L, 1)) {
        lua_pushfstring(L, "%s: the file name contains a NUL byte", fn);
        return LUA_ERRFILE;
    }
    if (!readable(L, path)) {
        lua_pushfstring(L, "%s('%s'): scripts may read only Lua files in lamina's "
                        "assets/lua, lamina's scripts/ and the script's folder", fn, path);
        return LUA_ERRFILE;
    }
    return luaL_loadfilex(L, path, "t");
}

static int sb_loadfile(lua_State *L)
{
    const char *path = luaL_checkstring(L, 1);
    const char *mode = luaL_optstring(L, 2, "t");
    if (strchr(mode, 'b'))
        return luaL_error(L, "loadfile: binary chunks are not allowed (mode '%s')", mode);
    int env = !lua_isnone(L, 3) ? 3 : 0;
    if (load_confined(L, "loadfile", path) != LUA_OK) {   /* as the stock one: nil, why */
        lua_pushnil(L);
        lua_insert(L, -2);
        return 2;
    }
    if (env) {   /* as the stock loadfile: env becomes the chunk's _ENV */
        lua_pushvalue(L, env);
        if (!lua_setupvalue(L, -2, 1)) lua_pop(L, 1);
    }
    return 1;
}

static int dofile_done(lua_State *L, int status, lua_KContext ctx)
{
    (void)status;
    (void)ctx;
    return lua_gettop(L) - 1;
}

static int sb_dofile(lua_State *L)
{
    const char *path = luaL_checkstring(L, 1);
    lua_settop(L, 1);
    if (load_confined(L, "dofile", path) != LUA_OK) return lua_error(L);
    lua_callk(L, 0, LUA_MULTRET, 0, dofile_done);
    return dofile_done(L, 0, 0);
}

/* load(chunk [, name [, mode [, env]]]) with mode forced to text; env is
 * passed on only when given (a nil env is not a missing one). */
static int sb_load(lua_State *L)
{
    int n = lua_gettop(L);
    const char *mode = luaL_optstring(L, 3, "t");
    if (strchr(mode, 'b'))
        return luaL_error(L, "load: binary chunks are not allowed (mode '%s')", mode);
    if (n < 4) lua_settop(L, 4);
    lua_pushvalue(L, lua_upvalueindex(1));
    lua_pushvalue(L, 1);
    lua_pushvalue(L, 2);
    lua_pushliteral(L, "t");
    int nargs = 3;
    if (n >= 4) {
        lua_pushvalue(L, 4);
        nargs = 4;
    }
    int base = lua_gettop(L) - nargs - 1;
    lua_call(L, nargs, LUA_MULTRET);
    return lua_gettop(L) - base;
}

/* ---- require --------------------------------------------------------- */

/* Module names are words joined by dots ("a.b" is a/b.lua): no slash, no
 * "..", nothing that could name a file outside the folder. */
static int module_name_ok(const char *name, size_t len)
{
    if (len == 0 || len > MAX_MODULE_NAME || strlen(name) != len) return 0;
    if (name[0] == '.' || name[len - 1] == '.' || strstr(name, "..")) return 0;
    for (size_t i = 0; i < len; i++) {
        unsigned char c = (unsigned char)name[i];
        int word = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') ||
                   (c >= '0' && c <= '9') || c == '_' || c == '-';
        if (!word && c != '.') return 0;
    }
    return 1;
}

/* The cache's mark for a module being loaded: a second require of it
 * before it returns is a loop (stock Lua recurses until "C stack
 * overflow"; a copied script named like the module it requires finds
 * itself first). */
static const char loading_mark = 0;

static int require_done(lua_State *L, int status, lua_KContext ctx)
{
    (void)ctx;
    /* stack: name, cache, path, result (or the error) */
    if (status != LUA_OK && status != LUA_YIELD) {
        lua_pushnil(L);                    /* unmark: a later require may try again */
        lua_setfield(L, 2, lua_tostring(L, 1));
        return lua_error(L);
    }
    if (lua_isnil(L, -1)) {
        lua_pop(L, 1);
        lua_pushboolean(L, 1);
    }
    lua_pushvalue(L, -1);
    lua_setfield(L, 2, lua_tostring(L, 1));
    lua_insert(L, -2);   /* result, path */
    return 2;
}

static int sb_require(lua_State *L)
{
    size_t len;
    const char *name = luaL_checklstring(L, 1, &len);
    lua_settop(L, 1);
    if (!module_name_ok(name, len))
        return luaL_error(L, "require: bad module name '%s' (words of letters, digits, "
                          "'_' and '-', joined by dots)", name);
    lua_getfield(L, LUA_REGISTRYINDEX, MODULES);   /* 2: the cache */
    if (lua_getfield(L, 2, name) != LUA_TNIL) {
        if (lua_touserdata(L, -1) == &loading_mark)
            return luaL_error(L, "require: module '%s' requires itself while it loads (a loop of "
                              "require calls; a script named '%s.lua' that requires '%s' finds "
                              "itself first: rename the script)", name, name, name);
        return 1;
    }
    lua_pop(L, 1);
    char file[MAX_MODULE_NAME + 8];
    snprintf(file, sizeof file, "%s.lua", name);
    for (char *c = file; *c && strcmp(c, ".lua") != 0; c++)
        if (*c == '.') *c = '/';
    lua_getfield(L, LUA_REGISTRYINDEX, REQUIRE_ROOTS);
    lua_Integer n = (lua_Integer)lua_rawlen(L, -1);
    for (lua_Integer i = 1; i <= n; i++) {
        lua_rawgeti(L, 3, i);
        const char *path = lua_pushfstring(L, "%s/%s", lua_tostring(L, -1), file);
        if (readable(L, path)) {
            lua_replace(L, 3);   /* 3: the path */
            lua_settop(L, 3);
            if (luaL_loadfilex(L, path, "t") != LUA_OK) return lua_error(L);
            lua_pushlightuserdata(L, (void *)&loading_mark);
            lua_setfield(L, 2, name);
            lua_pushvalue(L, 1);
            lua_pushvalue(L, 3);
            int st = lua_pcallk(L, 2, 1, 0, 0, require_done);
            return require_done(L, st, 0);
        }
        lua_pop(L, 2);
    }
    return luaL_error(L, "module '%s' not found (require reads lamina's assets/lua and "
                      "the script's folder only)", name);
}

/* ---- the rest --------------------------------------------------------- */

/* A metatable with __gc would run script code from inside the collector,
 * at any allocation of any binding. */
static int sb_setmetatable(lua_State *L)
{
    if (lua_istable(L, 2) && (lua_pushliteral(L, "__gc"), lua_rawget(L, 2)) != LUA_TNIL)
        return luaL_error(L, "setmetatable: __gc is not available to scripts");
    lua_settop(L, 2);
    lua_pushvalue(L, lua_upvalueindex(1));
    lua_insert(L, 1);
    lua_call(L, 2, 1);
    return 1;
}

/* "stop" would let a script grow without collection; "incremental" and
 * "generational" tune what the memory cap already bounds. */
static int sb_collectgarbage(lua_State *L)
{
    static const char *const opts[] = {"collect", "count", "step", "isrunning", NULL};
    luaL_checkoption(L, 1, "collect", opts);
    lua_pushvalue(L, lua_upvalueindex(1));
    lua_insert(L, 1);
    lua_call(L, lua_gettop(L) - 1, LUA_MULTRET);
    return lua_gettop(L);
}

/* io.write only, to stdout: the io library's files (io.stdout:close(),
 * :seek, :setvbuf, io.lines...) have no place in a scenario. */
static int sb_io_write(lua_State *L)
{
    int n = lua_gettop(L);
    for (int i = 1; i <= n; i++) {
        size_t len;
        const char *s = luaL_checklstring(L, i, &len);
        la_write_clean(stdout, s, len);   /* no terminal escapes (l_print.c) */
    }
    return 0;
}

/* Replaces global `name`, keeping the stock function as upvalue 1. */
static void wrap_global(lua_State *L, const char *name, lua_CFunction f)
{
    lua_getglobal(L, name);
    lua_pushcclosure(L, f, 1);
    lua_setglobal(L, name);
}

static void open_os(lua_State *L)
{
    static const char *const keep[] = {"clock", "time", "date", "difftime", NULL};
    luaopen_os(L);
    lua_createtable(L, 0, 4);
    for (int i = 0; keep[i]; i++) {
        lua_getfield(L, -2, keep[i]);
        lua_setfield(L, -2, keep[i]);
    }
    lua_setglobal(L, "os");
    lua_pop(L, 1);
}

void la_open_sandbox(lua_State *L, const char *script)
{
    static const luaL_Reg libs[] = {{LUA_GNAME, luaopen_base},
                                    {LUA_COLIBNAME, luaopen_coroutine},
                                    {LUA_TABLIBNAME, luaopen_table},
                                    {LUA_STRLIBNAME, luaopen_string},
                                    {LUA_MATHLIBNAME, luaopen_math},
                                    {LUA_UTF8LIBNAME, luaopen_utf8},
                                    {NULL, NULL}};
    for (const luaL_Reg *lib = libs; lib->func; lib++) {
        luaL_requiref(L, lib->name, lib->func, 1);
        lua_pop(L, 1);
    }
    lua_getglobal(L, "string");
    lua_pushnil(L);
    lua_setfield(L, -2, "dump");
    lua_pop(L, 1);
    la_guard_patterns(L);   /* the matcher's work capped: it cannot be interrupted */
    /* strings' metatable locked too: an __index function set on it would
     * run script code wherever a binding indexes a string */
    lua_pushliteral(L, "");
    if (lua_getmetatable(L, -1)) {
        lua_pushliteral(L, "locked");
        lua_setfield(L, -2, "__metatable");
        lua_pop(L, 1);
    }
    lua_pop(L, 1);
    open_os(L);
    lua_createtable(L, 0, 1);
    lua_pushcfunction(L, sb_io_write);
    lua_setfield(L, -2, "write");
    lua_setglobal(L, "io");

    la_open_print(L);
    wrap_global(L, "load", sb_load);
    wrap_global(L, "setmetatable", sb_setmetatable);
    wrap_global(L, "collectgarbage", sb_collectgarbage);
    lua_register(L, "loadfile", sb_loadfile);
    lua_register(L, "dofile", sb_dofile);
    lua_register(L, "require", sb_require);
    lua_newtable(L);
    lua_setfield(L, LUA_REGISTRYINDEX, MODULES);
    set_read_roots(L, script);
}
