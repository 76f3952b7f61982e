/* plot_csv.c - a plot's data as CSV, written atomically.
 *
 * The CSV is the plot's ground truth (docs/design.md, "Rendering": the
 * data are written as CSV too): every point, not the decimated polyline
 * that was drawn, with numbers that read back to the same doubles. */
#include "plot.h"

#include "atomic_file.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "util.h"


/* One header field, always quoted (RFC 4180; quotes doubled, though
 * lamina.plot refuses them): a label is free text (the legend's), and the
 * header is the file's first line. Quoted, and with no " $ ` or backslash
 * in a label (l_plot.c), the line is one shell word in which nothing
 * expands, and a Python tuple of plain strings: it runs as neither
 * (issue 31 item 2). */
static void put_field(FILE *fp, const char *label, size_t k, const char *axis)
{
    char buf[64];
    const char *s = label;
    if (!s || !*s) {
        snprintf(buf, sizeof buf, "series %zu", k + 1);
        s = buf;
    }
    fputc('"', fp);
    for (const char *c = s; *c; c++) {
        if (*c == '"')
            fputc('"', fp);
        fputc(*c, fp);
    }
    fprintf(fp, " %s\"", axis);
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

int lr_plot_write_csv(const lr_plot *p, const char *path, char *err, size_t errlen)
{
    if (!path || !*path) {
        lu_err(err, errlen, "cannot write CSV: empty path");
        return -1;
    }
    if (!p || (p->nseries > 0 && !p->series)) {
        lu_err(err, errlen, "cannot write '%s': no data", path);
        return -1;
    }
    for (size_t k = 0; k < p->nseries; k++)
        if (p->series[k].n > 0 && (!p->series[k].x || !p->series[k].y)) {
            lu_err(err, errlen, "cannot write '%s': series %zu has no arrays",
                    path, k + 1);
            return -1;
        }
    /* the one writer of every output (atomic_file.h): temporary, then
     * rename; folders made for a failed write are removed again */
    lr_atomic a;
    if (lr_atomic_open(&a, path, err, errlen) != 0)
        return -1;
    put_table(a.fp, p);
    return lr_atomic_commit(&a, err, errlen);
}
