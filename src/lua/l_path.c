/* l_path.c - where a script may write, and what text it may put in headers.
 *
 * Every file lamina writes for a script (frames, figures, plots and their
 * CSV, recorder CSV) is named by the script, and a script is untrusted
 * input (docs/design.md). So every such name goes through la_check_output_path
 * before anything is created: it must resolve inside the output root - the
 * working directory, or `lamina run --out-root DIR` - after "..", absolute
 * paths and symbolic links of the folders that exist are resolved; it must
 * hold no NUL byte (C would write "a" for "a\0b.png") and no control
 * character; an existing target must be a regular file (not /dev/null).
 * The folders still missing are created by the writer (atomic_file.c), as
 * real folders under the resolved parent, so they stay inside too. */
#define _XOPEN_SOURCE 700     /* realpath */
#include <errno.h>
#include <limits.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "l_internal.h"

#define OUT_ROOT "lamina.out_root"   /* registry: the real root, or absent */

int lamina_set_output_root(lua_State *L, const char *dir, char *err, size_t len)
{
    char real[PATH_MAX];
    struct stat st;
    if (!realpath(dir, real) || stat(real, &st) != 0) {
        snprintf(err, len, "--out-root '%s': %s", dir, strerror(errno));
        return -1;
    }
    if (!S_ISDIR(st.st_mode)) {
        snprintf(err, len, "--out-root '%s': not a directory", dir);
        return -1;
    }
    lua_pushstring(L, real);
    lua_setfield(L, LUA_REGISTRYINDEX, OUT_ROOT);
    return 0;
}

/* The root's real path into root (PATH_MAX bytes). */
static int output_root(lua_State *L, char *root)
{
    int ok;
    if (lua_getfield(L, LUA_REGISTRYINDEX, OUT_ROOT) == LUA_TSTRING) {
        snprintf(root, PATH_MAX, "%s", lua_tostring(L, -1));
        ok = 1;
    } else {
        ok = getcwd(root, PATH_MAX) != NULL;   /* physical: no links in it */
    }
    lua_pop(L, 1);
    return ok;
}

static int inside(const char *path, const char *root)
{
    size_t n = strlen(root);
    if (n == 1 && root[0] == '/') return path[1] != '\0';
    return strncmp(path, root, n) == 0 && path[n] == '/' && path[n + 1] != '\0';
}

/* Drops the last component of the absolute path p ("/a/b" -> "/a"). */
static void up(char *p)
{
    char *s = strrchr(p, '/');
    if (s == p) p[1] = '\0';
    else if (s) *s = '\0';
}

/* Where path would land: the absolute path with every existing component
 * resolved as the kernel will (symbolic links followed, ".." of the real
 * folder), the missing ones appended as they will be created. 0 or -1 when
 * too long. */
static int resolve(const char *path, char *out)
{
    char buf[PATH_MAX];
    if (path[0] == '/') strcpy(buf, "/");
    else if (!getcwd(buf, sizeof buf)) return -1;
    int exists = 1;   /* every component so far exists */
    const char *p = path;
    while (*p) {
        while (*p == '/') p++;
        size_t n = strcspn(p, "/");
        if (n == 0) break;
        int last = p[n] == '\0' || p[n + strspn(p + n, "/")] == '\0';
        if (n == 1 && p[0] == '.') {
            /* stays */
        } else if (n == 2 && p[0] == '.' && p[1] == '.') {
            up(buf);   /* buf is real while it exists; created folders are real */
        } else {
            size_t b = strlen(buf);
            if (b + 1 + n + 1 > sizeof buf) return -1;
            if (b > 1) buf[b++] = '/';
            memcpy(buf + b, p, n);
            buf[b + n] = '\0';
            struct stat st;
            if (exists && lstat(buf, &st) == 0) {
                char real[PATH_MAX];
                /* a link as the target itself is replaced by rename(2), not
                 * written through; a link as a folder is followed */
                if (!(last && S_ISLNK(st.st_mode)) && realpath(buf, real))
                    strcpy(buf, real);
            } else {
                exists = 0;
            }
        }
        p += n;
    }
    strcpy(out, buf);
    return 0;
}

/* Control characters would forge lines in a log or a CSV, and a file name
 * holding one is never what a scenario meant. */
static int has_control(const char *s, size_t len)
{
    for (size_t i = 0; i < len; i++)
        if ((unsigned char)s[i] < 0x20 || s[i] == 0x7f) return 1;
    return 0;
}

/* s with control characters shown as \ddd, pushed (for messages). */
static const char *printable(lua_State *L, const char *s, size_t len)
{
    luaL_Buffer b;
    luaL_buffinit(L, &b);
    for (size_t i = 0; i < len && i < 200; i++) {
        unsigned char c = (unsigned char)s[i];
        if (c < 0x20 || c == 0x7f) {
            char e[8];
            snprintf(e, sizeof e, "\\%d", c);
            luaL_addstring(&b, e);
        } else {
            luaL_addchar(&b, (char)c);
        }
    }
    luaL_pushresult(&b);
    return lua_tostring(L, -1);
}

const char *la_check_output_path(lua_State *L, const char *fn, int idx)
{
    idx = lua_absindex(L, idx);
    if (lua_type(L, idx) != LUA_TSTRING)
        luaL_error(L, "%s: the file name must be a string (got %s)", fn, luaL_typename(L, idx));
    size_t len;
    const char *path = lua_tolstring(L, idx, &len);
    if (len == 0) luaL_error(L, "%s: the file name is empty", fn);
    if (strlen(path) != len)
        luaL_error(L, "%s: cannot write '%s': the file name contains a NUL byte", fn,
                   printable(L, path, len));
    if (has_control(path, len))
        luaL_error(L, "%s: cannot write '%s': the file name contains a control character",
                   fn, printable(L, path, len));
    char root[PATH_MAX], where[PATH_MAX];
    if (!output_root(L, root))
        luaL_error(L, "%s: cannot write '%s': the working directory is unknown (%s)", fn,
                   path, strerror(errno));
    if (len >= PATH_MAX || resolve(path, where) != 0)
        luaL_error(L, "%s: cannot write '%s': the file name is too long", fn, path);
    if (!inside(where, root))
        luaL_error(L, "%s: cannot write '%s': it resolves to '%s', outside the output root "
                   "'%s' (the working directory, or lamina run --out-root DIR)",
                   fn, path, where, root);
    struct stat st;
    if (stat(where, &st) == 0 && !S_ISREG(st.st_mode))
        luaL_error(L, "%s: cannot write '%s': it exists and is not a regular file", fn, path);
    return path;
}

const char *la_opt_output_path(lua_State *L, int idx, const char *fn, const char *key)
{
    if (la_getfield(L, idx, key) == LUA_TNIL) {
        lua_pop(L, 1);
        return NULL;
    }
    if (lua_type(L, -1) != LUA_TSTRING)
        luaL_error(L, "%s: '%s' must be a string (got %s)", fn, key, luaL_typename(L, -1));
    const char *path = la_check_output_path(L, fn, -1);
    lua_pop(L, 1);   /* held by the table: reads are raw (la_getfield) */
    return path;
}

void la_check_text(lua_State *L, const char *fn, const char *what, const char *s)
{
    if (has_control(s, strlen(s)))
        luaL_error(L, "%s: %s '%s' contains a control character (newline, tab, ...)", fn,
                   what, printable(L, s, strlen(s)));
}
