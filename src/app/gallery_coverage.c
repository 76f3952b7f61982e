/* gallery_coverage.c - how much of the four papers the gallery covers
 * (issue 16, item 3).
 *
 * The data is hand-written: SCRIPTS/coverage.tsv, one row per figure or
 * table of a paper, tab-separated, '#' lines and empty lines skipped, the
 * first other line the column names:
 *
 *   paper  item      caption           status      pages              note
 *   M      Fig 12    angle theta ...   reproduced  membrane_pendulum  ...
 *
 *   paper   M, F, N or T (docs/physics.md, Sources)
 *   item    "Fig N" or "Table X", numbered as the paper numbers them
 *   status  reproduced | partial | missing
 *   pages   the figure scripts' names, comma-separated; "-" for none
 *   note    partial: what is missing; missing: what lamina would need
 *
 * `lamina gallery` renders it under the index (per-paper counts, then a
 * table per paper); `lamina gallery --check` keeps it from going stale:
 * every page it names is a script, every script is named, and every figure
 * or table a script's `source:` header cites is a row that names it, and
 * no row marked reproduced names a page with a failing check (a ✗).
 * A scripts folder without coverage.tsv (the test scenes) has no coverage
 * section and nothing to check. */
#include "gallery.h"

#include <ctype.h>
#include <stdlib.h>
#include <string.h>

static const char PAPERS[] = "MFNT";
static const char *const PAPER_NAMES[] = {
    "[M] York, Sulsky & Schreyer 1999, membranes (IJNME 44)",
    "[F] York, Sulsky & Schreyer 2000, fluid-membrane interaction (IJNME 48)",
    "[N] the normals paper (membrane normals without connectivity)",
    "[T] York's dissertation behind [M] and [F]",
};
static const char *const STATUSES[] = { "reproduced", "partial", "missing" };

typedef struct cov_row {
    char paper;
    char *item, *caption, *status, *pages, *note;
    int line;
} cov_row;

typedef struct g_coverage {
    cov_row *v;
    size_t n, cap;
    char *path;
} g_coverage;

static void coverage_free(g_coverage *c)
{
    for (size_t i = 0; i < c->n; i++) {
        free(c->v[i].item);
        free(c->v[i].caption);
        free(c->v[i].status);
        free(c->v[i].pages);
        free(c->v[i].note);
    }
    free(c->v);
    free(c->path);
    memset(c, 0, sizeof *c);
}

static int paper_index(char p)
{
    const char *q = p ? strchr(PAPERS, p) : NULL;
    return q ? (int)(q - PAPERS) : -1;
}

static int status_index(const char *s)
{
    for (int k = 0; k < 3; k++)
        if (s && strcmp(s, STATUSES[k]) == 0)
            return k;
    return -1;
}

/* Splits one line at tabs into at most 6 fields (copies, trimmed). */
static int split_tabs(const char *line, size_t len, char *f[6])
{
    int n = 0;
    const char *p = line, *end = line + len;
    while (n < 6) {
        const char *t = memchr(p, '\t', (size_t)(end - p));
        const char *e = t ? t : end;
        const char *a = p;
        while (a < e && (*a == ' ' || *a == '\r'))
            a++;
        const char *b = e;
        while (b > a && (b[-1] == ' ' || b[-1] == '\r'))
            b--;
        f[n++] = g_fmt("%.*s", (int)(b - a), a);
        if (!t)
            break;
        p = t + 1;
    }
    return n;
}

/* Reads SCRIPTS/coverage.tsv. Returns 1 when there is none, 0 when read
 * (rows that cannot be read are skipped and added to problems, if given),
 * -1 on a read error; c is to be freed only after 0 (nothing is kept
 * otherwise). */
static int coverage_read(const char *scripts, g_coverage *c, g_strs *problems)
{
    memset(c, 0, sizeof *c);
    c->path = g_fmt("%s/%s", scripts, G_COVERAGE);
    if (!g_exists(c->path)) {
        coverage_free(c);
        return 1;
    }
    char *text;
    size_t len;
    char err[512];
    if (g_read_file(c->path, &text, &len, err, sizeof err) != 0) {
        if (problems)
            g_strs_add(problems, g_strdup(err));
        coverage_free(c);
        return -1;
    }
    int lineno = 0, header = 0;
    for (const char *p = text; p < text + len;) {
        size_t n = strcspn(p, "\n");
        lineno++;
        const char *line = p;
        p += n + (p[n] == '\n');
        if (n == 0 || line[0] == '#')
            continue;
        if (!header) {                  /* the column names */
            header = 1;
            continue;
        }
        char *f[6] = { 0 };
        int nf = split_tabs(line, n, f);
        if (nf < 5 || paper_index(f[0][0]) < 0 || f[0][1] || status_index(f[3]) < 0 ||
            !(strncmp(f[1], "Fig ", 4) == 0 || strncmp(f[1], "Table ", 6) == 0)) {
            if (problems)
                g_strs_add(problems, g_fmt("%s:%d: not a row (want paper M|F|N|T, item "
                                           "'Fig N' or 'Table X', caption, status "
                                           "reproduced|partial|missing, pages, note, "
                                           "tab-separated)", c->path, lineno));
            for (int k = 0; k < nf; k++)
                free(f[k]);
            continue;
        }
        if (c->n == c->cap) {
            c->cap = c->cap ? 2 * c->cap : 64;
            cov_row *v = realloc(c->v, c->cap * sizeof *v);
            if (!v) {
                fputs("lamina gallery: out of memory\n", stderr);
                exit(2);
            }
            c->v = v;
        }
        cov_row *r = &c->v[c->n++];
        r->paper = f[0][0];
        free(f[0]);
        r->item = f[1];
        r->caption = f[2];
        r->status = f[3];
        r->pages = f[4];
        r->note = nf > 5 ? f[5] : g_strdup("");
        r->line = lineno;
    }
    free(text);
    return 0;
}

/* The page names of a row, split at commas. */
static void row_pages(const cov_row *r, g_strs *out)
{
    for (const char *p = r->pages; *p;) {
        p += strspn(p, ", ");
        size_t n = strcspn(p, ",");
        size_t m = n;
        while (m && p[m - 1] == ' ')
            m--;
        if (m && !(m == 1 && p[0] == '-'))
            g_strs_add(out, g_fmt("%.*s", (int)m, p));
        p += n;
    }
}

static int row_names(const cov_row *r, const char *stem)
{
    g_strs l = { 0 };
    row_pages(r, &l);
    int found = 0;
    for (size_t i = 0; i < l.n && !found; i++)
        found = strcmp(l.v[i], stem) == 0;
    g_strs_free(&l);
    return found;
}

/* A row marked reproduced claims the page shows the paper's numbers: each
 * of its pages' values that misses its tolerance (g_value_check, the rule
 * behind the page's ✗) is a problem naming the row and the value (issue 32
 * item 5). A page not rendered yet is gallery_check.c's problem, not this. */
static void check_reproduced(const g_options *o, const char *path, const cov_row *r,
                             const g_strs *pages, g_strs *problems)
{
    for (size_t k = 0; k < pages->n; k++) {
        char *meta = g_fmt("%s/%s/%s", o->gallery, pages->v[k], G_META);
        lu_json *m = g_exists(meta) ? gj_read(meta, NULL, 0) : NULL;
        const lu_json *vals = m ? lu_json_get(m, "values") : NULL;
        for (size_t i = 0; vals && vals->type == LU_JSON_ARRAY && i < vals->n; i++) {
            if (g_value_check(&vals->kids[i]) != 0)
                continue;
            char *line = g_value_line(&vals->kids[i]);
            g_strs_add(problems, g_fmt("%s:%d: [%c] %s is reproduced, but its page %s "
                                       "fails a check: %s (mark the row partial with "
                                       "what misses, or complete the page)", path,
                                       r->line, r->paper, r->item, pages->v[k], line));
            free(line);
        }
        lu_json_free(m);
        free(meta);
    }
}

/* ---- the figures a source header cites -------------------------------- */

/* The paper a phrase at p names, or 0. */
static char paper_at(const char *p)
{
    static const struct { const char *word; char paper; } words[] = {
        { "[M]", 'M' }, { "1999", 'M' }, { "(membranes)", 'M' },
        { "[F]", 'F' }, { "2000", 'F' }, { "(fluid-membrane)", 'F' },
        { "[N]", 'N' }, { "normals paper", 'N' },
        { "[T]", 'T' }, { "dissertation", 'T' },
    };
    for (size_t k = 0; k < sizeof words / sizeof words[0]; k++)
        if (strncmp(p, words[k].word, strlen(words[k].word)) == 0)
            return words[k].paper;
    return 0;
}

static int roman_value(char c)
{
    return c == 'I' ? 1 : c == 'V' ? 5 : c == 'X' ? 10 : 0;
}

/* A number at *p, arabic or (tables) roman; advances *p. 0 when none. */
static int number_at(const char **p, int *roman)
{
    const char *q = *p;
    if (isdigit((unsigned char)*q)) {
        int v = 0;
        while (isdigit((unsigned char)*q))
            v = 10 * v + (*q++ - '0');
        *p = q;
        *roman = 0;
        return v;
    }
    int v = 0;
    while (roman_value(*q)) {
        int a = roman_value(*q), b = roman_value(q[1]);
        v += a < b ? -a : a;
        q++;
    }
    if (q == *p || isalpha((unsigned char)*q))
        return 0;
    *p = q;
    *roman = 1;
    return v;
}

static char *roman_text(int v)
{
    static const struct { int v; const char *s; } r[] = {
        { 10, "X" }, { 9, "IX" }, { 5, "V" }, { 4, "IV" }, { 1, "I" } };
    char buf[32] = "";
    for (size_t k = 0; k < 5; k++)
        while (v >= r[k].v && strlen(buf) < sizeof buf - 4) {
            strcat(buf, r[k].s);
            v -= r[k].v;
        }
    return g_strdup(buf);
}

static void add_ref(g_strs *out, char paper, const char *kind, int v, int roman)
{
    char *num = roman ? roman_text(v) : g_fmt("%d", v);
    g_strs_add(out, g_fmt("%c %s %s", paper, kind, num));
    free(num);
}

/* After "Fig"/"Figs"/"Figure"/"Table"/"Tables": a list of numbers and
 * ranges ("8-12", "14, 15 and 16", "V-VI"). */
static const char *number_list(const char *p, char paper, const char *kind, g_strs *out)
{
    for (;;) {
        const char *q = p;
        int roman, roman2;
        int a = number_at(&q, &roman);
        if (!a || (roman && strcmp(kind, "Table") != 0))
            return p;
        int b = a;
        if (*q == '-' || strncmp(q, "–", strlen("–")) == 0) {
            const char *r = q + (*q == '-' ? 1 : strlen("–"));
            int c = number_at(&r, &roman2);
            if (c > a && roman2 == roman && c - a < 100) {
                b = c;
                q = r;
            }
        }
        for (int v = a; v <= b; v++)
            add_ref(out, paper, kind, v, roman);
        p = q;
        if (strncmp(p, ", ", 2) == 0 && (isdigit((unsigned char)p[2]) || roman_value(p[2])))
            p += 2;
        else if (strncmp(p, " and ", 5) == 0)
            p += 5;
        else
            return p;
    }
}

void g_source_refs(const char *source, g_strs *out)
{
    char paper = 0;
    for (const char *p = source; p && *p;) {
        char k = paper_at(p);
        if (k) {
            paper = k;
            p++;
            continue;
        }
        const char *kind = NULL;
        const char *q = p;
        if (strncmp(q, "Fig", 3) == 0 && (p == source || !isalpha((unsigned char)p[-1]))) {
            kind = "Fig";
            q += 3;
            if (strncmp(q, "ure", 3) == 0)
                q += 3;
        } else if (strncmp(q, "Table", 5) == 0 &&
                   (p == source || !isalpha((unsigned char)p[-1]))) {
            kind = "Table";
            q += 5;
        }
        if (kind) {
            if (*q == 's')
                q++;
            if (*q == '.')
                q++;
            while (*q == ' ')
                q++;
            if (paper) {
                const char *r = number_list(q, paper, kind, out);
                if (r != q) {
                    p = r;
                    continue;
                }
            }
        }
        p++;
    }
}

/* ---- checking --------------------------------------------------------- */

void g_coverage_check(const g_options *o, const g_scripts *all, g_strs *problems)
{
    g_coverage c;
    if (coverage_read(o->scripts, &c, problems) != 0)
        return;
    g_strs seen = { 0 };
    for (size_t i = 0; i < c.n; i++) {
        const cov_row *r = &c.v[i];
        char *key = g_fmt("%c %s", r->paper, r->item);
        for (size_t k = 0; k < seen.n; k++)
            if (strcmp(seen.v[k], key) == 0)
                g_strs_add(problems, g_fmt("%s:%d: [%c] %s is listed twice", c.path,
                                           r->line, r->paper, r->item));
        g_strs_add(&seen, key);
        g_strs pages = { 0 };
        row_pages(r, &pages);
        int st = status_index(r->status);
        if (st < 2 && pages.n == 0)
            g_strs_add(problems, g_fmt("%s:%d: [%c] %s is %s but names no page", c.path,
                                       r->line, r->paper, r->item, r->status));
        if (st == 2 && pages.n)
            g_strs_add(problems, g_fmt("%s:%d: [%c] %s is missing but names a page",
                                       c.path, r->line, r->paper, r->item));
        if (st > 0 && !*r->note)
            g_strs_add(problems, g_fmt("%s:%d: [%c] %s is %s: its note must say what %s",
                                       c.path, r->line, r->paper, r->item, r->status,
                                       st == 1 ? "is missing" : "lamina would need"));
        for (size_t k = 0; k < pages.n; k++) {
            int known = 0;
            for (size_t s = 0; s < all->n && !known; s++)
                known = strcmp(all->v[s].stem, pages.v[k]) == 0;
            if (!known)
                g_strs_add(problems, g_fmt("%s:%d: [%c] %s names the page %s, which has "
                                           "no script %s/%s.lua", c.path, r->line,
                                           r->paper, r->item, pages.v[k], o->scripts,
                                           pages.v[k]));
        }
        if (st == 0)
            check_reproduced(o, c.path, r, &pages, problems);
        g_strs_free(&pages);
    }
    g_strs_free(&seen);
    for (size_t s = 0; s < all->n; s++) {
        const g_script *sc = &all->v[s];
        int named = 0;
        for (size_t i = 0; i < c.n && !named; i++)
            named = row_names(&c.v[i], sc->stem);
        if (!named)
            g_strs_add(problems, g_fmt("%s: no row of %s names it", sc->path, c.path));
        g_strs refs = { 0 };
        g_source_refs(sc->h.source, &refs);
        for (size_t k = 0; k < refs.n; k++) {
            int again = 0;
            for (size_t j = 0; j < k && !again; j++)
                again = strcmp(refs.v[j], refs.v[k]) == 0;
            if (again)
                continue;
            int found = 0, listed = 0;
            for (size_t i = 0; i < c.n && !found; i++) {
                char *key = g_fmt("%c %s", c.v[i].paper, c.v[i].item);
                if (strcmp(key, refs.v[k]) == 0) {
                    listed = 1;
                    found = row_names(&c.v[i], sc->stem);
                }
                free(key);
            }
            if (!found)
                g_strs_add(problems, g_fmt("%s: its source cites [%c] %s, %s", sc->path,
                                           refs.v[k][0], refs.v[k] + 2,
                                           listed ? "whose row in coverage.tsv does not "
                                                    "name this page"
                                                  : "which coverage.tsv does not list"));
        }
        g_strs_free(&refs);
    }
    coverage_free(&c);
}

/* ---- rendering -------------------------------------------------------- */

static void counts(const g_coverage *c, int paper, int n[4])
{
    memset(n, 0, 4 * sizeof *n);
    for (size_t i = 0; i < c->n; i++)
        if (paper_index(c->v[i].paper) == paper) {
            int st = status_index(c->v[i].status);
            if (st >= 0)
                n[st]++;
            n[3]++;
        }
}

static const char *const INTRO =
    "Every figure and table of the four papers, and where the gallery shows it: "
    "**reproduced** (the page shows what the paper's figure shows, with its numbers), "
    "**partial** (the note says what is missing) or **missing** (the note says what "
    "lamina would need). The data is `%s`, written by hand; `lamina gallery --check` "
    "fails when it names a page that does not exist, or when a page's `source:` cites "
    "a figure whose row does not name the page.";

/* How a table row is written, in Markdown or HTML: what opens it, parts
 * its cells and closes it; text escaped; the link to a page (k: its place
 * in the row's list). */
typedef struct cov_style {
    const char *open, *sep, *close;
    void (*text)(FILE *f, const char *s);
    void (*link)(FILE *f, const char *page, size_t k);
} cov_style;

static void markdown_link(FILE *f, const char *page, size_t k)
{
    fputs(k ? ", [" : "[", f);
    g_markdown_cell(f, page);
    fputs("](", f);
    g_url(f, page);
    fprintf(f, "/%s)", G_PAGE);
}

static void html_link(FILE *f, const char *page, size_t k)
{
    fputs(k ? ", <a href=\"" : "<a href=\"", f);
    g_url(f, page);
    fprintf(f, "/%s\">", G_PAGE);
    g_html(f, page);
    fputs("</a>", f);
}

static const cov_style MARKDOWN = {"| ", " | ", " |\n", g_markdown_cell, markdown_link};
static const cov_style HTML = {"<tr><td class=\"num\">", "</td><td>", "</td></tr>\n", g_html,
                               html_link};

/* The rows of paper p: item, caption, status (one of three plain words,
 * the same escaped or not), pages, note. */
static void write_rows(FILE *f, const g_coverage *c, int p, const cov_style *s)
{
    for (size_t i = 0; i < c->n; i++) {
        const cov_row *r = &c->v[i];
        if (paper_index(r->paper) != p)
            continue;
        fputs(s->open, f);
        s->text(f, r->item);
        fputs(s->sep, f);
        s->text(f, r->caption);
        fputs(s->sep, f);
        s->text(f, r->status);
        fputs(s->sep, f);
        g_strs pages = { 0 };
        row_pages(r, &pages);
        for (size_t k = 0; k < pages.n; k++)
            s->link(f, pages.v[k], k);
        g_strs_free(&pages);
        fputs(s->sep, f);
        s->text(f, r->note);
        fputs(s->close, f);
    }
}

void g_coverage_markdown(FILE *f, const g_options *o)
{
    g_coverage c;
    if (coverage_read(o->scripts, &c, NULL) != 0)
        return;
    fputs("\n## Coverage of the papers\n\n", f);
    fprintf(f, INTRO, c.path);
    fputs("\n\n| Paper | Figures and tables | Reproduced | Partial | Missing |\n"
          "| --- | --- | --- | --- | --- |\n", f);
    for (int p = 0; p < 4; p++) {
        int n[4];
        counts(&c, p, n);
        fprintf(f, "| %s | %d | %d | %d | %d |\n", PAPER_NAMES[p], n[3], n[0], n[1], n[2]);
    }
    for (int p = 0; p < 4; p++) {
        fprintf(f, "\n### %s\n\n| Item | Caption | Status | Page | Note |\n"
                   "| --- | --- | --- | --- | --- |\n", PAPER_NAMES[p]);
        write_rows(f, &c, p, &MARKDOWN);
    }
    coverage_free(&c);
}

void g_coverage_html(FILE *f, const g_options *o)
{
    g_coverage c;
    if (coverage_read(o->scripts, &c, NULL) != 0)
        return;
    fputs("<h2>Coverage of the papers</h2>\n<p>", f);
    char *intro = g_fmt(INTRO, c.path);
    for (const char *s = intro; *s; s++)      /* the Markdown's bold and code, as text */
        if (*s != '*' && *s != '`')
            g_html(f, (char[2]){ *s, 0 });
    free(intro);
    fputs("</p>\n<table>\n<tr><th>Paper</th><th>Figures and tables</th><th>Reproduced</th>"
          "<th>Partial</th><th>Missing</th></tr>\n", f);
    for (int p = 0; p < 4; p++) {
        int n[4];
        counts(&c, p, n);
        fputs("<tr><td>", f);
        g_html(f, PAPER_NAMES[p]);
        fprintf(f, "</td><td>%d</td><td>%d</td><td>%d</td><td>%d</td></tr>\n", n[3], n[0],
                n[1], n[2]);
    }
    fputs("</table>\n", f);
    for (int p = 0; p < 4; p++) {
        fputs("<h3>", f);
        g_html(f, PAPER_NAMES[p]);
        fputs("</h3>\n<table>\n<tr><th>Item</th><th>Caption</th><th>Status</th><th>Page</th>"
              "<th>Note</th></tr>\n", f);
        write_rows(f, &c, p, &HTML);
        fputs("</table>\n", f);
    }
    coverage_free(&c);
}
