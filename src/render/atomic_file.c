/* atomic_file.c - temporary, then rename: see atomic_file.h. */
#include "atomic_file.h"
#include "stale_temp.h"

#include <errno.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include "util.h"

/* Makes sure dir exists as a directory, creating it if missing; *made is
 * set when this call created it. */
static int ensure_dir(const char *dir, const char *path, int *made, char *err, size_t errlen)
{
    struct stat st;
    *made = 0;
    if (stat(dir, &st) != 0) {
        if (errno != ENOENT) {
            lu_err(err, errlen, "cannot write '%s': '%s': %s", path, dir,
                    strerror(errno));
            return -1;
        }
        if (mkdir(dir, 0777) == 0) {
            *made = 1;
            return 0;
        }
        /* another process may have created it in between */
        if (errno != EEXIST || stat(dir, &st) != 0) {
            lu_err(err, errlen, "cannot write '%s': cannot create directory "
                    "'%s': %s", path, dir, strerror(errno));
            return -1;
        }
    }
    if (!S_ISDIR(st.st_mode)) {
        lu_err(err, errlen, "cannot write '%s': '%s' is not a directory",
                path, dir);
        return -1;
    }
    return 0;
}

/* Removes the folders a->dir created, deepest first (rmdir: only while
 * empty, so nothing another writer put there is lost). */
static void remove_made(lr_atomic *a)
{
    if (!a->dir) return;
    size_t len = strlen(a->dir);
    while (a->made && len >= a->made) {
        a->dir[len] = '\0';
        if (rmdir(a->dir) != 0) break;
        while (len > 0 && a->dir[len - 1] != '/') len--;   /* up one */
        while (len > 1 && a->dir[len - 1] == '/') len--;
        if (len == 0) break;
    }
    free(a->dir);
    a->dir = NULL;
    a->made = 0;
}

/* mkdir -p for the directory part of path; remembers in a what it made. */
static int make_parents(lr_atomic *a, const char *path, char *err, size_t errlen)
{
    const char *slash = strrchr(path, '/');
    if (!slash || slash == path)
        return 0;   /* the current directory or the root: both exist */
    size_t len = (size_t)(slash - path);
    char *dir = malloc(len + 1);
    if (!dir) {
        lu_err(err, errlen, "cannot write '%s': out of memory", path);
        return -1;
    }
    memcpy(dir, path, len);
    dir[len] = '\0';
    int rc = 0;
    a->dir = dir;
    a->made = 0;
    for (size_t i = 1; i <= len && rc == 0; i++) {
        if (i < len && (dir[i] != '/' || dir[i - 1] == '/'))
            continue;   /* not the end of a component (or a repeated '/') */
        char keep = dir[i];
        dir[i] = '\0';
        int made;
        rc = ensure_dir(dir, path, &made, err, errlen);
        dir[i] = keep;
        if (made && !a->made) a->made = i;
    }
    if (rc != 0) {
        remove_made(a);
        return -1;
    }
    if (!a->made) {   /* nothing created: nothing to undo */
        free(a->dir);
        a->dir = NULL;
    }
    return 0;
}

static int check_target(const char *path, char *err, size_t errlen)
{
    struct stat st;
    if (stat(path, &st) == 0 && !S_ISREG(st.st_mode)) {
        lu_err(err, errlen, "cannot write '%s': it exists and is not a "
                "regular file", path);
        return -1;
    }
    return 0;
}

/* mkstemp creates mode 0600; an output should get the mode any new file of
 * this process gets (0666 less the umask), and umask can only be read by
 * setting it. Output is written from one thread, so the brief change is
 * safe. */
static int give_default_mode(int fd)
{
    mode_t mask = umask(0);
    umask(mask);
    return fchmod(fd, 0666 & ~mask);
}

int lr_atomic_open(lr_atomic *a, const char *path, char *err, size_t errlen)
{
    memset(a, 0, sizeof *a);
    if (!path || !*path) {
        lu_err(err, errlen, "cannot write: empty path");
        return -1;
    }
    if (check_target(path, err, errlen) != 0 || make_parents(a, path, err, errlen) != 0)
        return -1;
    a->path = path;
    lr_remove_stale_temps(path);   /* left by a killed run (stale_temp.h) */
    /* "<path>.tmp.<host>.<pid>.XXXXXX": same directory, so rename(2) stays
     * atomic; the owner in the name lets a later run remove it */
    a->tmp = lr_temp_template(path);
    if (!a->tmp) {
        lu_err(err, errlen, "cannot write '%s': out of memory", path);
        remove_made(a);
        return -1;
    }
    int fd = mkstemp(a->tmp);
    if (fd < 0) {
        lu_err(err, errlen, "cannot write '%s': cannot create temporary "
                "file: %s", path, strerror(errno));
        free(a->tmp);
        a->tmp = NULL;
        remove_made(a);
        return -1;
    }
    if (give_default_mode(fd) != 0 || !(a->fp = fdopen(fd, "wb"))) {
        int e = errno;
        close(fd);
        unlink(a->tmp);
        lu_err(err, errlen, "cannot write '%s': %s", path, strerror(e));
        free(a->tmp);
        a->tmp = NULL;
        remove_made(a);
        return -1;
    }
    return 0;
}

int lr_atomic_abort(lr_atomic *a, const char *why, char *err, size_t errlen)
{
    if (a->fp)
        fclose(a->fp);
    a->fp = NULL;
    if (a->tmp && unlink(a->tmp) != 0)
        lu_err(err, errlen, "cannot write '%s': %s (and cannot remove "
                "temporary '%s': %s)", a->path, why, a->tmp, strerror(errno));
    else
        lu_err(err, errlen, "cannot write '%s': %s", a->path, why);
    free(a->tmp);
    a->tmp = NULL;
    remove_made(a);
    return -1;
}

int lr_atomic_commit(lr_atomic *a, char *err, size_t errlen)
{
    int bad = ferror(a->fp) || fflush(a->fp) != 0;
    int e = errno;
    if (fclose(a->fp) != 0 && !bad) {
        bad = 1;
        e = errno;
    }
    a->fp = NULL;
    if (!bad && rename(a->tmp, a->path) != 0) {
        bad = 1;
        e = errno;
    }
    if (bad)
        return lr_atomic_abort(a, e ? strerror(e) : "write error", err, errlen);
    free(a->tmp);
    a->tmp = NULL;
    free(a->dir);   /* the folders stay: they hold the file */
    a->dir = NULL;
    return 0;
}

int lr_write_file(const char *path, const void *data, size_t n, char *err, size_t errlen)
{
    lr_atomic a;
    if (lr_atomic_open(&a, path, err, errlen) != 0)
        return -1;
    if (n && fwrite(data, 1, n, a.fp) != n)
        return lr_atomic_abort(&a, strerror(errno), err, errlen);
    return lr_atomic_commit(&a, err, errlen);
}
