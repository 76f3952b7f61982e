/* plot_csv.c - a plot's data as CSV, written atomically.
 *
 * The CSV is the plot's ground truth (design.md, Rendering: "data also
 * written as CSV"): every point, not the decimated polyline that was drawn,
 * with numbers that read back to the same doubles. */
#include "plot.h"

#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

static void set_err(char *err, size_t errlen, const char *fmt, ...)
{
    if (!err || errlen == 0)
        return;
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(err, errlen, fmt, ap);
    va_end(ap);
}

/* Creates every missing folder above path (mkdir -p of its directory). A
 * folder that appears meanwhile (EEXIST) is fine; something else in the way
 * is reported. */
static int make_folders(const char *path, char *err, size_t errlen)
{
    size_t len = strlen(path);
    char *dir = malloc(len + 1);
    if (!dir) {
        set_err(err, errlen, "cannot write '%s': out of memory", path);
        return -1;
    }
    memcpy(dir, path, len + 1);
    int rc = 0;
    for (size_t i = 1; i < len && rc == 0; i++) {
        if (dir[i] != '/' || dir[i - 1] == '/')
            continue;
        dir[i] = '\0';
        struct stat st;
        if (stat(dir, &st) != 0) {
            if (mkdir(dir, 0777) != 0 && errno != EEXIST) {
                set_err(err, errlen, "cannot write '%s': cannot create folder "
                        "'%s': %s", path, dir, strerror(errno));
                rc = -1;
            }
        } else if (!S_ISDIR(st.st_mode)) {
            set_err(err, errlen, "cannot write '%s': '%s' is not a folder", path, dir);
            rc = -1;
        }
        dir[i] = '/';
    }
    free(dir);
    return rc;
}

/* One header field, quoted (RFC 4180) when it holds a separator, a quote,
 * a line break or edge spaces that a reader could trim. */
static void put_field(FILE *fp, const char *label, size_t k, const char *axis)
{
    char buf[64];
    const char *s = label;
    if (!s || !*s) {
        snprintf(buf, sizeof buf, "series %zu", k + 1);
        s = buf;
    }
    size_t n = strlen(s);
    int quote = strpbrk(s, ",\"\r\n") != NULL || s[0] == ' ' || s[n - 1] == ' ';
    if (quote)
        fputc('"', fp);
    for (const char *c = s; *c; c++) {
        if (*c == '"')
            fputc('"', fp);
        fputc(*c, fp);
    }
    fprintf(fp, " %s", axis);
    if (quote)
        fputc('"', fp);
}

/* The shortest %.Ng (N = 15..17) that reads back as v: 0.1 stays "0.1"
 * instead of 0.10000000000000001, and nothing is lost. */
static void put_number(FILE *fp, double v)
{
    if (isnan(v)) {
        fputs("nan", fp);
        return;
    }
    if (isinf(v)) {
        fputs(v > 0 ? "inf" : "-inf", fp);
        return;
    }
    char buf[40];
    for (int prec = 15; prec <= 17; prec++) {
        snprintf(buf, sizeof buf, "%.*g", prec, v);
        if (strtod(buf, NULL) == v)
            break;
    }
    fputs(buf, fp);
}

static void put_table(FILE *fp, const lr_plot *p)
{
    size_t rows = 0;
    for (size_t k = 0; k < p->nseries; k++) {
        const lr_plot_series *s = &p->series[k];
        if (k)
            fputc(',', fp);
        put_field(fp, s->label, k, "x");
        fputc(',', fp);
        put_field(fp, s->label, k, "y");
        if (s->n > rows)
            rows = s->n;
    }
    fputc('\n', fp);
    for (size_t i = 0; i < rows; i++) {
        for (size_t k = 0; k < p->nseries; k++) {
            const lr_plot_series *s = &p->series[k];
            if (k)
                fputc(',', fp);
            if (i < s->n)
                put_number(fp, s->x[i]);
            fputc(',', fp);
            if (i < s->n)
                put_number(fp, s->y[i]);
        }
        fputc('\n', fp);
    }
}

/* Writes the table through the temporary file descriptor fd (closed in
 * every case); *why says what failed. */
static int write_temp(int fd, const lr_plot *p, char *why, size_t whylen)
{
    /* mkstemp makes 0600; a CSV gets what any new file of ours gets */
    mode_t mask = umask(0);
    umask(mask);
    if (fchmod(fd, 0666 & ~mask) != 0) {
        snprintf(why, whylen, "%s", strerror(errno));
        close(fd);
        return -1;
    }
    FILE *fp = fdopen(fd, "w");
    if (!fp) {
        snprintf(why, whylen, "%s", strerror(errno));
        close(fd);
        return -1;
    }
    put_table(fp, p);
    int rc = 0;
    if (ferror(fp) || fflush(fp) != 0) {
        snprintf(why, whylen, "%s", errno ? strerror(errno) : "write error");
        rc = -1;
    }
    if (fclose(fp) != 0 && rc == 0) {
        snprintf(why, whylen, "%s", strerror(errno));
        rc = -1;
    }
    return rc;
}

int lr_plot_write_csv(const lr_plot *p, const char *path, char *err, size_t errlen)
{
    if (!path || !*path) {
        set_err(err, errlen, "cannot write CSV: empty path");
        return -1;
    }
    if (!p || (p->nseries > 0 && !p->series)) {
        set_err(err, errlen, "cannot write '%s': no data", path);
        return -1;
    }
    for (size_t k = 0; k < p->nseries; k++)
        if (p->series[k].n > 0 && (!p->series[k].x || !p->series[k].y)) {
            set_err(err, errlen, "cannot write '%s': series %zu has no arrays",
                    path, k + 1);
            return -1;
        }
    if (make_folders(path, err, errlen) != 0)
        return -1;
    /* rename(2) would replace a device, FIFO or folder at path */
    struct stat st;
    if (stat(path, &st) == 0 && !S_ISREG(st.st_mode)) {
        set_err(err, errlen, "cannot write '%s': it exists and is not a regular file",
                path);
        return -1;
    }
    static const char suffix[] = ".tmp.XXXXXX";   /* same folder: atomic rename */
    size_t n = strlen(path);
    char *tmp = malloc(n + sizeof suffix);
    if (!tmp) {
        set_err(err, errlen, "cannot write '%s': out of memory", path);
        return -1;
    }
    memcpy(tmp, path, n);
    memcpy(tmp + n, suffix, sizeof suffix);
    int fd = mkstemp(tmp);
    if (fd < 0) {
        set_err(err, errlen, "cannot write '%s': cannot create temporary file: %s",
                path, strerror(errno));
        free(tmp);
        return -1;
    }
    char why[256] = "";
    errno = 0;
    int rc = write_temp(fd, p, why, sizeof why);
    if (rc == 0 && rename(tmp, path) != 0) {
        snprintf(why, sizeof why, "%s", strerror(errno));
        rc = -1;
    }
    if (rc != 0) {
        if (unlink(tmp) == 0)
            set_err(err, errlen, "cannot write '%s': %s", path, why);
        else
            set_err(err, errlen, "cannot write '%s': %s (and cannot remove "
                    "temporary '%s': %s)", path, why, tmp, strerror(errno));
    }
    free(tmp);
    return rc;
}
