/* gallery_fs.c - the file chores of the gallery: paths, whole-file reads,
 * atomic writes (lr_write_file: a reader - git, a browser, the next run -
 * never sees half a file), folder listings in a fixed (sorted) order so
 * that output does not depend on readdir. */
#define _XOPEN_SOURCE 700     /* realpath */
#include "gallery.h"

#include "atomic_file.h"
#include "read_file.h"

#include <dirent.h>
#include <errno.h>
#include <limits.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include "util.h"

static void out_of_memory(void)
{
    fprintf(stderr, "lamina gallery: out of memory\n");
    exit(2);
}

void *g_alloc(size_t n)
{
    void *p = calloc(1, n ? n : 1);
    if (!p)
        out_of_memory();
    return p;
}

char *g_fmt(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    int n = vsnprintf(NULL, 0, fmt, ap);
    va_end(ap);
    if (n < 0)
        out_of_memory();
    char *s = g_alloc((size_t)n + 1);
    va_start(ap, fmt);
    vsnprintf(s, (size_t)n + 1, fmt, ap);
    va_end(ap);
    return s;
}

char *g_strdup(const char *s)
{
    return g_fmt("%s", s ? s : "");
}

void g_strs_add(g_strs *l, char *owned)
{
    if (lu_reserve(&l->v, &l->cap, l->n + 1, sizeof *l->v, 16) != 0)
        out_of_memory();
    l->v[l->n++] = owned;
}

static int cmp_str(const void *a, const void *b)
{
    return strcmp(*(char *const *)a, *(char *const *)b);
}

void g_strs_sort(g_strs *l)
{
    if (l->n > 1)
        qsort(l->v, l->n, sizeof *l->v, cmp_str);
}

void g_strs_free(g_strs *l)
{
    for (size_t i = 0; i < l->n; i++)
        free(l->v[i]);
    free(l->v);
    l->v = NULL;
    l->n = l->cap = 0;
}

int g_has_suffix(const char *s, const char *suffix)
{
    size_t n = strlen(s), m = strlen(suffix);
    return n >= m && strcmp(s + n - m, suffix) == 0;
}

int g_exists(const char *path)
{
    struct stat st;
    return stat(path, &st) == 0;
}

int g_is_dir(const char *path)
{
    struct stat st;
    return stat(path, &st) == 0 && S_ISDIR(st.st_mode);
}

int g_read_file(const char *path, char **text, size_t *len, char *err, size_t errlen)
{
    /* a regular file of at most LR_READ_MAX bytes: a report.json linked to
     * /dev/zero was read for ever (issue 18) */
    char why[1024];
    if (lr_read_file(path, LR_READ_MAX, text, len, why, sizeof why) != 0) {
        lu_err(err, errlen, "%s", why);
        return -1;
    }
    return 0;
}

int g_mkdirs(const char *dir, char *err, size_t errlen)
{
    char *p = g_strdup(dir);
    int rc = 0;
    for (char *q = p + 1; rc == 0; q++) {
        int end = *q == '\0';
        if (!end && *q != '/')
            continue;
        *q = '\0';
        if (mkdir(p, 0777) != 0 && errno != EEXIST) {
            lu_err(err, errlen, "cannot create folder '%s': %s", p, strerror(errno));
            rc = -1;
        } else if (!g_is_dir(p)) {
            lu_err(err, errlen, "cannot create folder '%s': a file is in the way", p);
            rc = -1;
        }
        if (end)
            break;
        *q = '/';
    }
    free(p);
    return rc;
}

int g_write_file(const char *path, const char *text, size_t len, char *err, size_t errlen)
{
    return lr_write_file(path, text, len, err, errlen);
}

int g_copy_file(const char *from, const char *to, char *err, size_t errlen)
{
    char *text;
    size_t len;
    if (g_read_file(from, &text, &len, err, errlen) != 0)
        return -1;
    int rc = g_write_file(to, text, len, err, errlen);
    free(text);
    return rc;
}

/* Removes path and, for a folder, everything inside; lstat so that a
 * symbolic link is removed, never followed. */
static int remove_tree(const char *path, char *err, size_t errlen)
{
    struct stat st;
    if (lstat(path, &st) != 0)
        return errno == ENOENT ? 0 : (lu_err(err, errlen, "cannot remove '%s': %s", path,
                                              strerror(errno)), -1);
    if (S_ISDIR(st.st_mode)) {
        if (g_clear_dir(path, err, errlen) != 0)
            return -1;
        if (rmdir(path) != 0) {
            lu_err(err, errlen, "cannot remove '%s': %s", path, strerror(errno));
            return -1;
        }
        return 0;
    }
    if (unlink(path) != 0) {
        lu_err(err, errlen, "cannot remove '%s': %s", path, strerror(errno));
        return -1;
    }
    return 0;
}

/* The entries of dir except . and .., sorted; a missing dir is empty. */
static int entries(const char *dir, g_strs *out, char *err, size_t errlen)
{
    DIR *d = opendir(dir);
    if (!d) {
        if (errno == ENOENT)
            return 0;
        lu_err(err, errlen, "cannot read folder '%s': %s", dir, strerror(errno));
        return -1;
    }
    struct dirent *e;
    while ((e = readdir(d)) != NULL)
        if (strcmp(e->d_name, ".") && strcmp(e->d_name, ".."))
            g_strs_add(out, g_strdup(e->d_name));
    closedir(d);
    g_strs_sort(out);
    return 0;
}

int g_clear_dir(const char *dir, char *err, size_t errlen)
{
    g_strs names = { 0 };
    int rc = entries(dir, &names, err, errlen);
    for (size_t i = 0; rc == 0 && i < names.n; i++) {
        char *p = g_fmt("%s/%s", dir, names.v[i]);
        rc = remove_tree(p, err, errlen);
        free(p);
    }
    g_strs_free(&names);
    return rc;
}

static int list_under(const char *root, const char *rel, g_strs *out, char *err,
                      size_t errlen)
{
    char *dir = rel ? g_fmt("%s/%s", root, rel) : g_strdup(root);
    g_strs names = { 0 };
    int rc = entries(dir, &names, err, errlen);
    for (size_t i = 0; rc == 0 && i < names.n; i++) {
        /* a hidden file is never a page's output (no output name may start
         * with a dot, docs/security.md): the run's own list of outputs,
         * .lamina-outputs, stays off the page */
        if (names.v[i][0] == '.')
            continue;
        char *r = rel ? g_fmt("%s/%s", rel, names.v[i]) : g_strdup(names.v[i]);
        char *full = g_fmt("%s/%s", root, r);
        struct stat st;
        if (lstat(full, &st) == 0 && S_ISDIR(st.st_mode)) {
            rc = list_under(root, r, out, err, errlen);
            free(r);
        } else if (S_ISREG(st.st_mode)) {
            g_strs_add(out, r);
        } else {
            free(r);
        }
        free(full);
    }
    g_strs_free(&names);
    free(dir);
    return rc;
}

int g_list_files(const char *dir, g_strs *out, char *err, size_t errlen)
{
    int rc = list_under(dir, NULL, out, err, errlen);
    g_strs_sort(out);
    return rc;
}

int g_list_dirs(const char *dir, g_strs *out, char *err, size_t errlen)
{
    g_strs names = { 0 };
    int rc = entries(dir, &names, err, errlen);
    for (size_t i = 0; rc == 0 && i < names.n; i++) {
        char *p = g_fmt("%s/%s", dir, names.v[i]);
        if (g_is_dir(p))
            g_strs_add(out, g_strdup(names.v[i]));
        free(p);
    }
    g_strs_free(&names);
    return rc;
}

char *g_relpath(const char *from, const char *to)
{
    char a[PATH_MAX], b[PATH_MAX];
    if (!realpath(from, a) || !realpath(to, b))
        return NULL;
    /* c: the end of the longest common prefix that ends at a folder boundary */
    size_t c = 0;
    for (size_t i = 0;; i++) {
        int end_a = a[i] == '/' || a[i] == '\0', end_b = b[i] == '/' || b[i] == '\0';
        if (end_a && end_b)
            c = i;
        if (a[i] != b[i] || !a[i])
            break;
    }
    g_text t;
    g_text_open(&t);
    for (size_t i = c; a[i]; i++)
        if (a[i] == '/' && a[i + 1])
            fputs("../", t.f);
    fputs(b + c + (b[c] == '/'), t.f);
    g_text_close(&t);
    return t.buf;
}

char *g_abspath(const char *path)
{
    char buf[PATH_MAX];
    return g_strdup(realpath(path, buf) ? buf : path);
}

void g_text_open(g_text *t)
{
    t->buf = NULL;
    t->len = 0;
    t->f = open_memstream(&t->buf, &t->len);
    if (!t->f)
        out_of_memory();
}

void g_text_close(g_text *t)
{
    if (fclose(t->f) != 0 || !t->buf)
        out_of_memory();
    t->f = NULL;
}
