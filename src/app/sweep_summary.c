/* sweep_summary.c - the table of a sweep, built from its run folders.
 *
 * One row per run: its folder, its parameters, exit status, wall time, the
 * values it reported (report.json) and, for a failed run, the first error
 * line of its log. Written as summary.csv (RFC 4180 quoting) and
 * summary.md, atomically; the Markdown table is also printed. Columns are
 * the union over the runs, in the order first met. */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "atomic_file.h"
#include "sweep.h"
#include "util.h"

static char *path_in(const char *folder, const char *file)
{
    size_t n = strlen(folder) + strlen(file) + 2;
    char *p = malloc(n);
    if (p) snprintf(p, n, "%s/%s", folder, file);
    return p;
}

/* Appends a copy of s to the list of n; the capacity doubles at every
 * power of two, so appending stays linear overall. */
static int push(char ***list, int n, const char *s)
{
    char *copy = strdup(s);
    if (!copy) return -1;
    if ((n & (n - 1)) == 0) {
        char **l = realloc(*list, (size_t)(n ? 2 * n : 1) * sizeof *l);
        if (!l) {
            free(copy);
            return -1;
        }
        *list = l;
    }
    (*list)[n] = copy;
    return 0;
}

/* Lines of the log that are not errors: progress, live changes, the frame
 * count, tracebacks. */
static int is_noise(const char *line)
{
    static const char *const prefixes[] = {"lamina: progress", "lamina: t = ",
                                           "stack traceback:", "\t", "report: ", NULL};
    if (!line[0]) return 1;
    for (int i = 0; prefixes[i]; i++)
        if (strncmp(line, prefixes[i], strlen(prefixes[i])) == 0) return 1;
    return strncmp(line, "lamina: ", 8) == 0 && strstr(line, " written to ") != NULL;
}

static char *first_error(const char *folder)
{
    char *path = path_in(folder, SW_STDERR);
    FILE *f = path ? fopen(path, "r") : NULL;
    free(path);
    if (!f) return NULL;
    struct stat st;   /* a log linked to /dev/zero is one endless line */
    if (fstat(fileno(f), &st) != 0 || !S_ISREG(st.st_mode)) {
        fclose(f);
        return NULL;
    }
    char *line = NULL, *found = NULL;
    size_t cap = 0;
    ssize_t n;
    while (!found && (n = getline(&line, &cap, f)) >= 0) {
        while (n > 0 && (line[n - 1] == '\n' || line[n - 1] == '\r')) line[--n] = 0;
        if (!is_noise(line))
            found = strdup(strncmp(line, "lamina: ", 8) == 0 ? line + 8 : line);
    }
    free(line);
    fclose(f);
    return found;
}

int sw_row_load(const char *folder, sw_row *row)
{
    memset(row, 0, sizeof *row);
    row->wall = -1;
    char *path = path_in(folder, SW_RECORD);
    FILE *f = path ? fopen(path, "r") : NULL;
    free(path);
    if (!f) return -1;
    struct stat st;   /* a record linked to /dev/zero is one endless line */
    if (fstat(fileno(f), &st) != 0 || !S_ISREG(st.st_mode) || st.st_size > (1 << 20)) {
        fclose(f);
        errno = 0;
        return -1;
    }
    const char *slash = strrchr(folder, '/');
    row->label = strdup(slash ? slash + 1 : folder);
    snprintf(row->status, sizeof row->status, "unfinished");
    char *line = NULL;
    size_t cap = 0;
    ssize_t n;
    int magic = 0;
    while ((n = getline(&line, &cap, f)) >= 0) {
        if (n > 0 && line[n - 1] == '\n') line[--n] = 0;
        if (strcmp(line, "lamina sweep run") == 0) {
            magic = 1;
        } else if (strncmp(line, "set ", 4) == 0) {
            char *eq = strchr(line + 4, '=');
            if (!eq) continue;
            *eq = 0;
            if (push(&row->pnames, row->nparams, line + 4) == 0 &&
                push(&row->pvalues, row->nparams, eq + 1) == 0)
                row->nparams++;
        } else if (strncmp(line, "status ", 7) == 0) {
            snprintf(row->status, sizeof row->status, "%s", line + 7);
        } else if (strncmp(line, "wall ", 5) == 0) {
            row->wall = strtod(line + 5, NULL);
        }
    }
    free(line);
    fclose(f);
    if (!magic || !row->label) {
        sw_row_free(row);
        return -1;
    }
    row->ok = strcmp(row->status, "0") == 0;
    path = path_in(folder, SW_REPORT);
    char **names, **values;
    int nrep;
    if (path && sw_report_read(path, &names, &values, &nrep) == 0) {
        row->rnames = names;
        row->rvalues = values;
        row->nrep = nrep;
    }
    free(path);
    if (!row->ok) row->error = first_error(folder);
    return 0;
}

void sw_row_free(sw_row *row)
{
    for (int i = 0; i < row->nparams; i++) {
        free(row->pnames[i]);
        free(row->pvalues[i]);
    }
    for (int i = 0; i < row->nrep; i++) {
        free(row->rnames[i]);
        free(row->rvalues[i]);
    }
    LU_FREE_ALL(row->pnames, row->pvalues, row->rnames, row->rvalues, row->label, row->error);
    memset(row, 0, sizeof *row);
}

/* ---- order ------------------------------------------------------------ */

static const char *lookup(char **names, char **values, int n, const char *name)
{
    for (int i = 0; i < n; i++)
        if (strcmp(names[i], name) == 0) return values[i];
    return NULL;
}

static int compare_values(const char *a, const char *b)
{
    if (!a || !b) return a ? 1 : b ? -1 : 0;
    char *ea, *eb;
    double x = strtod(a, &ea), y = strtod(b, &eb);
    if (ea != a && !*ea && eb != b && !*eb && x != y) return x < y ? -1 : 1;
    return strcmp(a, b);
}

static int compare_rows(const void *pa, const void *pb)
{
    const sw_row *a = pa, *b = pb;
    for (int i = 0; i < a->nparams; i++) {
        const char *vb = lookup(b->pnames, b->pvalues, b->nparams, a->pnames[i]);
        int c = compare_values(a->pvalues[i], vb);
        if (c) return c;
    }
    return strcmp(a->label, b->label);
}

void sw_rows_sort(sw_row *rows, int n)
{
    if (n > 1) qsort(rows, (size_t)n, sizeof *rows, compare_rows);
}

/* ---- columns and output ------------------------------------------------- */

typedef struct columns {
    char **params, **reports;
    int np, nr;
    sw_index pix, rix;   /* the names above, found in constant time */
} columns;

static int add_unique(char ***list, int *n, sw_index *ix, const char *name)
{
    if (sw_index_get(ix, name) >= 0) return 0;
    if (push(list, *n, name)) return -1;
    if (sw_index_put(ix, (*list)[*n], *n)) return -1;
    (*n)++;
    return 0;
}

static int gather(const sw_row *rows, int n, columns *c)
{
    memset(c, 0, sizeof *c);
    for (int r = 0; r < n; r++) {
        for (int i = 0; i < rows[r].nparams; i++)
            if (add_unique(&c->params, &c->np, &c->pix, rows[r].pnames[i])) return -1;
        for (int i = 0; i < rows[r].nrep; i++)
            if (add_unique(&c->reports, &c->nr, &c->rix, rows[r].rnames[i])) return -1;
    }
    return 0;
}

/* Row w's report values in column order (NULL where it has none), so that
 * writing a row is linear in its columns. */
static const char **report_cells(const sw_row *w, const columns *c)
{
    const char **cell = calloc((size_t)(c->nr ? c->nr : 1), sizeof *cell);
    if (!cell) return NULL;
    for (int i = w->nrep - 1; i >= 0; i--) {   /* backwards: the first wins */
        int k = sw_index_get(&c->rix, w->rnames[i]);
        if (k >= 0) cell[k] = w->rvalues[i];
    }
    return cell;
}

static void free_columns(columns *c)
{
    for (int i = 0; i < c->np; i++) free(c->params[i]);
    for (int i = 0; i < c->nr; i++) free(c->reports[i]);
    free(c->params);
    free(c->reports);
    sw_index_free(&c->pix);
    sw_index_free(&c->rix);
}

static void csv_field(FILE *f, const char *s, int first)
{
    if (!first) fputc(',', f);
    if (!s) return;
    if (!strpbrk(s, ",\"\n\r")) {
        fputs(s, f);
        return;
    }
    fputc('"', f);
    for (; *s; s++) {
        if (*s == '"') fputc('"', f);
        fputc(*s, f);
    }
    fputc('"', f);
}

static void md_field(FILE *f, const char *s)
{
    char num[32];
    char *end;
    if (s && *s && strchr(s, '.')) {   /* a reported number: 6 digits are for reading */
        double v = strtod(s, &end);
        if (!*end && snprintf(num, sizeof num, "%.6g", v) > 0) s = num;
    }
    fputs(" ", f);
    /* a reported string is the script's: no raw HTML in the page (Markdown
     * viewers render it: "<script>" ran in some), no terminal escape in the
     * copy printed (issue 31 item 8) */
    for (; s && *s; s++) {
        const char *ent = lu_xml_entity(*s);
        if (*s == '|') fputs("\\|", f);
        else if (*s == '"') fputc('"', f);   /* text, not an attribute */
        else if (ent) fputs(ent, f);
        else if ((unsigned char)*s < 0x20 || *s == 0x7f) fputc(' ', f);
        else fputc(*s, f);
    }
    fputs(" |", f);
}

static void write_csv(FILE *f, const sw_row *rows, int n, const columns *c)
{
    csv_field(f, "run", 1);
    for (int i = 0; i < c->np; i++) csv_field(f, c->params[i], 0);
    csv_field(f, "status", 0);
    csv_field(f, "wall_s", 0);
    for (int i = 0; i < c->nr; i++) csv_field(f, c->reports[i], 0);
    csv_field(f, "error", 0);
    fputc('\n', f);
    for (int r = 0; r < n; r++) {
        const sw_row *w = &rows[r];
        char wall[32] = "";
        if (w->wall >= 0) snprintf(wall, sizeof wall, "%.2f", w->wall);
        csv_field(f, w->label, 1);
        for (int i = 0; i < c->np; i++)
            csv_field(f, lookup(w->pnames, w->pvalues, w->nparams, c->params[i]), 0);
        csv_field(f, w->status, 0);
        csv_field(f, wall, 0);
        const char **cell = report_cells(w, c);
        for (int i = 0; i < c->nr; i++)
            csv_field(f, cell ? cell[i] : lookup(w->rnames, w->rvalues, w->nrep, c->reports[i]),
                      0);
        free(cell);
        csv_field(f, w->error, 0);
        fputc('\n', f);
    }
}

static void write_md_table(FILE *f, const sw_row *rows, int n, const columns *c)
{
    fputs("| run |", f);
    for (int i = 0; i < c->np; i++) md_field(f, c->params[i]);
    fputs(" status | wall (s) |", f);
    for (int i = 0; i < c->nr; i++) md_field(f, c->reports[i]);
    fputs(" error |\n|---|", f);
    for (int i = 0; i < c->np + 2 + c->nr + 1; i++) fputs("---|", f);
    fputc('\n', f);
    for (int r = 0; r < n; r++) {
        const sw_row *w = &rows[r];
        char wall[32] = "";
        if (w->wall >= 0) snprintf(wall, sizeof wall, "%.2f", w->wall);
        fputs("|", f);
        md_field(f, w->label);
        for (int i = 0; i < c->np; i++)
            md_field(f, lookup(w->pnames, w->pvalues, w->nparams, c->params[i]));
        md_field(f, w->status);
        md_field(f, wall);
        const char **cell = report_cells(w, c);
        for (int i = 0; i < c->nr; i++)
            md_field(f, cell ? cell[i] : lookup(w->rnames, w->rvalues, w->nrep, c->reports[i]));
        free(cell);
        md_field(f, w->error);
        fputc('\n', f);
    }
}

static int write_one(const char *dir, const char *file, const char *title, const sw_row *rows,
                     int n, const columns *c, int md)
{
    char *path = path_in(dir, file);
    if (!path) return -1;
    char err[600];
    lr_atomic a;
    int rc = lr_atomic_open(&a, path, err, sizeof err);
    if (rc == 0) {
        if (md) {
            int failed = 0;
            for (int r = 0; r < n; r++) failed += !rows[r].ok;
            fprintf(a.fp, "# %s\n\n%d run%s, %d failed.\n\n", title, n, n == 1 ? "" : "s",
                    failed);
            write_md_table(a.fp, rows, n, c);
        } else {
            write_csv(a.fp, rows, n, c);
        }
        rc = lr_atomic_commit(&a, err, sizeof err);
    }
    if (rc) fprintf(stderr, "lamina sweep: %s\n", err);
    free(path);
    return rc;
}

int sw_summary_write(const char *dir, const char *title, sw_row *rows, int n, FILE *out)
{
    columns c;
    if (gather(rows, n, &c)) {
        free_columns(&c);
        fprintf(stderr, "lamina sweep: out of memory\n");
        return -1;
    }
    int rc = write_one(dir, "summary.csv", title, rows, n, &c, 0);
    if (!rc) rc = write_one(dir, "summary.md", title, rows, n, &c, 1);
    if (out) write_md_table(out, rows, n, &c);
    free_columns(&c);
    return rc;
}
