/* l_outputs.c - which existing files a script may replace (issue 31 item 1).
 *
 * A script names its outputs, and a script is untrusted: without a rule it
 * could replace any regular file under the output root (a project's
 * conftest.py, Makefile, run.sh). So an existing file is replaced only when
 * lamina wrote it, in this run or an earlier one. Lamina knows that from:
 *
 *  - the manifest ROOT/.lamina-outputs: one line per file written for a
 *    script, its path relative to the output root (resolved: no link, no
 *    "." or ".."). A line is appended, with one write(2) on an O_APPEND
 *    descriptor, when the path is first accepted for writing, so runs in
 *    parallel (a sweep) do not tear each other's lines. The name starts
 *    with a dot, and no script may name a component that does (l_path.c),
 *    so no script can write or replace the manifest itself;
 *  - the file's own provenance, for outputs older than the manifest: a PNG
 *    with the tEXt chunk Software = "lamina ..." before its image data (every
 *    image lamina writes carries it: l_provenance.c), or a checkpoint
 *    starting with its magic line.
 *
 * Anything else (and any symbolic link, which lamina never makes) is
 * refused naming the file. The set read from the manifest is kept in the
 * registry; a miss reads the file again, for lines another process added. */
#define _XOPEN_SOURCE 700
#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "l_internal.h"
#include "read_file.h"

#define MANIFEST ".lamina-outputs"
#define SET_KEY "lamina.outputs"      /* registry: {relative path = true} */
#define SET_FROM "lamina.outputs_of"  /* registry: the manifest it came from */

/* The manifest's path for the root into out (PATH_MAX). */
static void manifest_path(const char *root, char *out, size_t len)
{
    snprintf(out, len, "%s%s" MANIFEST, root, strcmp(root, "/") ? "/" : "");
}

/* Pushes the set of relative paths read from the manifest of root; when
 * fresh, the file is read again (an absent manifest is an empty set). */
static void push_set(lua_State *L, const char *root, int fresh)
{
    char mpath[PATH_MAX + sizeof MANIFEST + 1];
    manifest_path(root, mpath, sizeof mpath);
    int have = lua_getfield(L, LUA_REGISTRYINDEX, SET_KEY) == LUA_TTABLE;
    lua_getfield(L, LUA_REGISTRYINDEX, SET_FROM);
    int same = lua_isstring(L, -1) && strcmp(lua_tostring(L, -1), mpath) == 0;
    lua_pop(L, 1);
    if (have && same && !fresh) return;
    lua_pop(L, 1);
    lua_newtable(L);
    char *text = NULL, err[PATH_MAX + 128];
    size_t len = 0;
    struct stat st;
    if (lstat(mpath, &st) == 0 && lr_read_file(mpath, LR_READ_MAX, &text, &len, err,
                                                sizeof err) == 0) {
        const char *p = text, *end = text + len;
        while (p < end) {
            const char *eol = memchr(p, '\n', (size_t)(end - p));
            if (!eol) break;   /* a torn last line (a killed writer) is no entry */
            if (eol > p) {
                lua_pushlstring(L, p, (size_t)(eol - p));
                lua_pushboolean(L, 1);
                lua_rawset(L, -3);
            }
            p = eol + 1;
        }
        free(text);
    }
    lua_pushvalue(L, -1);
    lua_setfield(L, LUA_REGISTRYINDEX, SET_KEY);
    lua_pushstring(L, mpath);
    lua_setfield(L, LUA_REGISTRYINDEX, SET_FROM);
}

static int in_set(lua_State *L, const char *rel)
{
    lua_getfield(L, -1, rel);
    int yes = lua_toboolean(L, -1);
    lua_pop(L, 1);
    return yes;
}

/* 1 when the regular file at path starts as a lamina PNG (signature, then
 * chunks up to IDAT, one of them tEXt "Software\0lamina ") or a lamina
 * checkpoint. Reads at most the first 64 KiB. */
static int has_own_provenance(const char *path)
{
    static const unsigned char sig[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    static const char soft[] = "Software\0lamina ";   /* key, NUL, value prefix */
    static const char ck[] = "LAMINA-CHECKPOINT";
    int fd = open(path, O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) return 0;
    unsigned char buf[65536];
    ssize_t n = read(fd, buf, sizeof buf);
    close(fd);
    if (n <= 0) return 0;
    size_t len = (size_t)n;
    if (len >= sizeof ck - 1 && memcmp(buf, ck, sizeof ck - 1) == 0) return 1;
    if (len < 8 || memcmp(buf, sig, 8) != 0) return 0;
    size_t at = 8;
    while (at + 8 <= len) {
        size_t clen = (size_t)buf[at] << 24 | (size_t)buf[at + 1] << 16 |
                      (size_t)buf[at + 2] << 8 | buf[at + 3];
        const unsigned char *type = buf + at + 4;
        if (memcmp(type, "IDAT", 4) == 0) return 0;
        if (clen > len - at - 8) return 0;   /* beyond what was read */
        if (memcmp(type, "tEXt", 4) == 0 && clen >= sizeof soft - 1 &&
            memcmp(buf + at + 8, soft, sizeof soft - 1) == 0)
            return 1;
        at += 12 + clen;   /* length, type, data, CRC */
    }
    return 0;
}

int la_output_owned(lua_State *L, const char *root, const char *rel, const char *where)
{
    push_set(L, root, 0);
    int yes = in_set(L, rel);
    lua_pop(L, 1);
    if (!yes) {   /* perhaps written since by another run */
        push_set(L, root, 1);
        yes = in_set(L, rel);
        lua_pop(L, 1);
    }
    return yes || has_own_provenance(where);
}

int la_output_note(lua_State *L, const char *root, const char *rel, char *err, size_t len)
{
    push_set(L, root, 0);
    if (in_set(L, rel)) {
        lua_pop(L, 1);
        return 0;
    }
    char mpath[PATH_MAX + sizeof MANIFEST + 1];
    manifest_path(root, mpath, sizeof mpath);
    int fd = open(mpath, O_WRONLY | O_APPEND | O_CREAT | O_NOFOLLOW | O_CLOEXEC, 0666);
    size_t n = strlen(rel);
    char line[PATH_MAX + 2];
    memcpy(line, rel, n);
    line[n] = '\n';
    int ok = fd >= 0 && write(fd, line, n + 1) == (ssize_t)(n + 1);
    int e = errno;
    if (fd >= 0 && close(fd) != 0 && ok) {
        ok = 0;
        e = errno;
    }
    if (!ok) {
        lua_pop(L, 1);
        snprintf(err, len, "cannot note it in '%s' (the list of lamina's outputs): %s", mpath,
                 strerror(e));
        return -1;
    }
    lua_pushboolean(L, 1);
    lua_setfield(L, -2, rel);
    lua_pop(L, 1);
    return 0;
}
