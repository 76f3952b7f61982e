/* l_path.c - where a script may write, and what text it may put in headers.
 *
 * Every file lamina writes for a script (frames, figures, plots and their
 * CSV, recorder CSV, VTK series, checkpoints) is named by the script, and a
 * script is untrusted input (docs/design.md, docs/security.md). So every
 * such name goes through la_check_output_path before anything is created:
 *
 *  - it holds no NUL byte (C would write "a" for "a\0b.png") and no control
 *    character;
 *  - it is resolved component by component against the real file system
 *    (resolve below): every component that exists is replaced by its real
 *    path (links followed, ".." of the real folder); from the first missing
 *    component on, the rest is created by the writer as real folders, so a
 *    ".." there is refused - the kernel would resolve it only after the
 *    folder is made, through whatever link sits beside it (issue 31:
 *    "out/nosuch/../link/x.png" wrote through out/link);
 *  - the result lies inside the output root (the working directory, or
 *    `lamina run --out-root DIR`), and no component of the name as given
 *    or as resolved under the root starts with a dot ("." and ".." as given
 *    only navigate): no .bashrc, .git/hooks, nor lamina's own manifest;
 *  - an existing target is a regular file that lamina wrote (l_outputs.c:
 *    the manifest of outputs, or a PNG/checkpoint's own provenance); a link,
 *    device or anyone else's file is refused, naming it.
 *
 * Accepted paths are noted in the manifest, so a later run may replace
 * them. Nothing can change the tree between the check and the write but
 * lamina's own writers (a script makes no links and runs no programs). */
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

/* Why resolve refused a path. */
enum { RES_OK = 0, RES_LONG = -1, RES_DOTDOT = -2, RES_DOT = -3 };

/* Where path would land: the absolute path with every existing component
 * resolved as the kernel will (symbolic links followed, ".." of the real
 * folder), the missing ones appended as the writer will create them.
 * RES_DOTDOT for a ".." after a missing component, RES_DOT for a component
 * starting with a dot other than "." and "..", RES_LONG when too long. */
static int resolve(const char *path, char *out)
{
    char buf[PATH_MAX];
    if (path[0] == '/') strcpy(buf, "/");
    else if (!getcwd(buf, sizeof buf)) return RES_LONG;
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
            if (!exists) return RES_DOTDOT;
            up(buf);   /* buf is real: every component so far exists */
        } else if (p[0] == '.') {
            return RES_DOT;
        } else {
            size_t b = strlen(buf);
            if (b + 1 + n + 1 > sizeof buf) return RES_LONG;
            if (b > 1) buf[b++] = '/';
            memcpy(buf + b, p, n);
            buf[b + n] = '\0';
            struct stat st;
            if (exists && lstat(buf, &st) == 0) {
                char real[PATH_MAX];
                /* a link as the target itself is not followed: it is
                 * refused below (lamina never writes one); a link as a
                 * folder is followed to where it leads */
                if (!(last && S_ISLNK(st.st_mode))) {
                    if (!realpath(buf, real)) return RES_LONG;
                    strcpy(buf, real);
                }
            } else {
                exists = 0;
            }
        }
        p += n;
    }
    strcpy(out, buf);
    return RES_OK;
}

/* The first component of rel (a path relative to the root) starting with
 * a dot, or NULL. */
static const char *dot_component(const char *rel)
{
    for (const char *p = rel; *p; p += strcspn(p, "/")) {
        while (*p == '/') p++;
        if (*p == '.') return p;
    }
    return NULL;
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

/* The checks every path gets, writing or reading: a string, no NUL or
 * control character, resolved inside the root. where (PATH_MAX) gets the
 * resolved path, root (PATH_MAX) the root; returns the path. */
/* The name at idx: a string, not empty, without NUL or control characters. */
static const char *plain_name(lua_State *L, const char *fn, int idx, const char *verb,
                              size_t *len)
{
    if (lua_type(L, idx) != LUA_TSTRING)
        luaL_error(L, "%s: the file name must be a string (got %s)", fn, luaL_typename(L, idx));
    const char *path = lua_tolstring(L, idx, len);
    if (*len == 0) luaL_error(L, "%s: the file name is empty", fn);
    if (strlen(path) != *len)
        luaL_error(L, "%s: cannot %s '%s': the file name contains a NUL byte", fn, verb,
                   printable(L, path, *len));
    if (has_control(path, *len))
        luaL_error(L, "%s: cannot %s '%s': the file name contains a control character",
                   fn, verb, printable(L, path, *len));
    return path;
}

static const char *confined(lua_State *L, const char *fn, int idx, const char *verb,
                            char *root, char *where)
{
    size_t len;
    const char *path = plain_name(L, fn, idx, verb, &len);
    if (!output_root(L, root))
        luaL_error(L, "%s: cannot %s '%s': the working directory is unknown (%s)", fn,
                   verb, path, strerror(errno));
    int r = len >= PATH_MAX ? RES_LONG : resolve(path, where);
    if (r == RES_LONG)
        luaL_error(L, "%s: cannot %s '%s': the file name is too long", fn, verb, path);
    if (r == RES_DOTDOT)
        luaL_error(L, "%s: cannot %s '%s': '..' after a folder that does not exist "
                   "(it would be resolved only once made, through what lies beside it)",
                   fn, verb, path);
    if (r == RES_DOT)
        luaL_error(L, "%s: cannot %s '%s': a name in it starts with a dot (hidden files "
                   "and folders are not outputs)", fn, verb, path);
    if (!inside(where, root))
        luaL_error(L, "%s: cannot %s '%s': it resolves to '%s', outside the output root "
                   "'%s' (the working directory, or lamina run --out-root DIR)",
                   fn, verb, path, where, root);
    return path;
}

/* A resolved path's part below base (a folder it is inside), refused with
 * the first name in it that starts with a dot: hidden files and folders
 * are not `what` (outputs, read). */
static const char *visible_below(lua_State *L, const char *fn, const char *verb,
                                 const char *path, const char *resolved, const char *base,
                                 const char *what)
{
    const char *rel = resolved + strlen(base) + (strcmp(base, "/") != 0);
    const char *dot = dot_component(rel);
    if (dot)
        luaL_error(L, "%s: cannot %s '%s': it resolves to '%s', where '%s' starts with a dot "
                   "(hidden files and folders are not %s)", fn, verb, path, resolved, dot,
                   what);
    return rel;
}

const char *la_check_output_path(lua_State *L, const char *fn, int idx)
{
    idx = lua_absindex(L, idx);
    char root[PATH_MAX], where[PATH_MAX];
    const char *path = confined(L, fn, idx, "write", root, where);
    const char *rel = visible_below(L, fn, "write", path, where, root, "outputs");
    struct stat st;
    if (lstat(where, &st) == 0) {
        if (S_ISLNK(st.st_mode))
            luaL_error(L, "%s: cannot write '%s': it is a symbolic link (lamina replaces only "
                       "files it wrote)", fn, path);
        if (!S_ISREG(st.st_mode))
            luaL_error(L, "%s: cannot write '%s': it exists and is not a regular file", fn,
                       path);
        if (!la_output_owned(L, root, rel, where))
            luaL_error(L, "%s: cannot write '%s': it exists and lamina did not write it (it "
                       "is not in %s/.lamina-outputs and carries no lamina provenance); "
                       "remove it or choose another name", fn, path, root);
    }
    char err[PATH_MAX + 160];
    if (la_output_note(L, root, rel, err, sizeof err) != 0)
        luaL_error(L, "%s: cannot write '%s': %s", fn, path, err);
    return path;
}

const char *la_check_input_path(lua_State *L, const char *fn, int idx)
{
    char root[PATH_MAX], where[PATH_MAX];
    return confined(L, fn, lua_absindex(L, idx), "read", root, where);
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

/* A name that becomes a field of a CSV header line (issue 31 item 2): the
 * header is a file's first line, and a first line of `$(...)`, `;` or
 * `import os` runs when someone does `sh energy.csv` or `python3 x.csv`
 * (a CSV named conftest.py is collected by pytest). Letters, digits, space
 * and _ . - ( ) [ ] / make no shell or Python statement that runs: such a
 * line is at worst an unknown command or name. */
void la_check_csv_name(lua_State *L, const char *fn, const char *what, const char *s)
{
    size_t n = strlen(s);
    for (size_t i = 0; i < n; i++) {
        unsigned char c = (unsigned char)s[i];
        if ((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
            strchr("_.-()[]/ ", c))
            continue;
        luaL_error(L, "%s: %s '%s' may hold only letters, digits, spaces and _ . - ( ) [ ] / "
                   "(it heads a CSV column; '%s' is not allowed)", fn, what,
                   printable(L, s, n), printable(L, s + i, 1));
    }
}

/* A file that comes with the script (l_internal.h): read only, so no
 * ownership check, but confined as outputs are (docs/security.md
 * "Paths"): inside the script's folder or the output root after links are
 * resolved, nothing hidden (a script in the home folder must not reach
 * .ssh/ through a mesh's error messages), a regular file (a FIFO or
 * /dev/zero would block or never end), at most max bytes. */
const char *la_check_asset_path(lua_State *L, const char *fn, int idx, size_t max, char *real,
                                size_t *size)
{
    idx = lua_absindex(L, idx);
    size_t len;
    const char *path = plain_name(L, fn, idx, "read", &len);
    char folder[PATH_MAX], root[PATH_MAX], full[2 * PATH_MAX + 2];
    if (!la_script_folder(L, folder, sizeof folder) && !getcwd(folder, sizeof folder))
        luaL_error(L, "%s: cannot read '%s': the working directory is unknown (%s)", fn, path,
                   strerror(errno));
    if (!output_root(L, root))
        luaL_error(L, "%s: cannot read '%s': the working directory is unknown (%s)", fn, path,
                   strerror(errno));
    if (path[0] == '/') snprintf(full, sizeof full, "%s", path);
    else snprintf(full, sizeof full, "%s/%s", folder, path);
    if (strlen(full) >= PATH_MAX)
        luaL_error(L, "%s: cannot read '%s': the file name is too long", fn, path);
    if (!realpath(full, real))
        luaL_error(L, "%s: cannot read '%s' (looked for '%s'): %s", fn, path, full,
                   strerror(errno));
    const char *base = inside(real, folder) ? folder : inside(real, root) ? root : NULL;
    if (!base)
        luaL_error(L, "%s: cannot read '%s': it resolves to '%s', outside the script's folder "
                   "'%s' and the output root '%s'", fn, path, real, folder, root);
    visible_below(L, fn, "read", path, real, base, "read");
    struct stat st;
    if (stat(real, &st) != 0 || !S_ISREG(st.st_mode))
        luaL_error(L, "%s: cannot read '%s': not a regular file", fn, path);
    if ((size_t)st.st_size > max)
        luaL_error(L, "%s: cannot read '%s': %lld bytes, more than the limit of %zu", fn, path,
                   (long long)st.st_size, max);
    *size = (size_t)st.st_size;
    return path;
}
