/* gallery_index.c - what a person reads: the index (gallery/README.md for
 * GitHub, gallery/index.html for a browser, same table) and a page per
 * figure (gallery/<stem>/README.md).
 *
 * Everything is written from the scripts' headers and each figure's
 * meta.json, never from memory of this run, so an index written after
 * rendering one figure still lists all of them. Links are relative and the
 * HTML has no external assets: the folder works when copied anywhere.
 * Only thumbnails and pages are linked from the index (they are
 * committed); the full-size images are linked from the pages. */
#include "gallery.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static int reserved(const char *name)
{
    return !strcmp(name, G_THUMB) || !strcmp(name, G_PAGE) || !strcmp(name, G_META) ||
           !strcmp(name, G_REPORT) || !strcmp(name, G_LOG) || strstr(name, ".tmp.");
}

int g_outputs(const char *dir, g_strs *images, g_strs *data, char *err, size_t errlen)
{
    g_strs files = { 0 };
    if (g_list_files(dir, &files, err, errlen) != 0)
        return -1;
    for (size_t i = 0; i < files.n; i++) {
        char *f = files.v[i];
        files.v[i] = NULL;
        if (reserved(f))
            free(f);
        else if (g_has_suffix(f, ".png"))
            g_strs_add(images, f);
        else if (data)
            g_strs_add(data, f);
        else
            free(f);
    }
    g_strs_free(&files);
    return 0;
}

const char *g_key_image(const g_script *s, const g_strs *images)
{
    for (size_t i = 0; s->h.thumb && i < images->n; i++)
        if (strcmp(images->v[i], s->h.thumb) == 0)
            return images->v[i];
    return images->n ? images->v[images->n - 1] : NULL;
}

/* ---- escaping ---------------------------------------------------------- */

/* One character of a script's text in Markdown, which passes raw HTML on
 * to the page: a '<' that could open a tag, comment or declaration is
 * written &lt; (issue 31 item 8: "-- title: <img src=x onerror=...>" ran in
 * a viewer); "r <= 0.1" stays as it is. Other control characters than the
 * line breaks become spaces. 1 when c was written. */
static int markdown_char(FILE *f, const char *s)
{
    unsigned char c = (unsigned char)*s, n = (unsigned char)s[1];
    if (c == '<' && (n == '/' || n == '!' || n == '?' || (unsigned)((n | 0x20) - 'a') < 26u)) {
        fputs("&lt;", f);
        return 1;
    }
    if ((c < 0x20 && c != '\n' && c != '\r' && c != '\t') || c == 0x7f) {
        fputc(' ', f);
        return 1;
    }
    return 0;
}

void g_markdown_text(FILE *f, const char *s)
{
    for (; s && *s; s++)
        if (!markdown_char(f, s)) fputc(*s, f);
}

void g_markdown_cell(FILE *f, const char *s)
{
    for (; s && *s; s++) {
        if (*s == '|')
            fputs("\\|", f);
        else if (*s == '\n' || *s == '\r')
            fputc(' ', f);
        else if (!markdown_char(f, s))
            fputc(*s, f);
    }
}

/* s as one segment of a relative URL (issue 31: a script's file name went
 * raw into href and src): every byte but the unreserved A-Z a-z 0-9 - . _ ~
 * percent-encoded, so the result holds nothing HTML or Markdown reads
 * (no quote, <, >, &, space, parenthesis or bracket) and no '/' or ':' that
 * would change where the link leads. */
void g_url(FILE *f, const char *s)
{
    for (; s && *s; s++) {
        unsigned char c = (unsigned char)*s;
        if ((c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') ||
            c == '-' || c == '.' || c == '_' || c == '~')
            fputc(c, f);
        else
            fprintf(f, "%%%02X", c);
    }
}

/* A script's file name in a Markdown cell: as g_markdown_cell, and also
 * < > & " as entities - a name is not meant to carry markup, and a
 * Markdown renderer passes inline HTML through (issue 31). */
static void markdown_name(FILE *f, const char *s)
{
    for (; s && *s; s++) {
        const char *e = lu_xml_entity(*s);
        if (e) fputs(e, f);
        else if (*s == '|') fputs("\\|", f);
        else if (*s == '\n' || *s == '\r') fputc(' ', f);
        else fputc(*s, f);
    }
}

void g_html(FILE *f, const char *s)
{
    for (; s && *s; s++) {
        const char *e = lu_xml_entity(*s);
        if (e)
            fputs(e, f);
        else
            fputc(*s, f);
    }
}

/* ---- reported values --------------------------------------------------- */

/* A value for a table: integers as written, other numbers to 4 digits. */
static char *show(const lu_json *v)
{
    if (!v)
        return NULL;
    switch (v->type) {
    case LU_JSON_NUMBER:
        if (!strpbrk(v->text, ".eE"))
            return g_strdup(v->text);
        return g_fmt("%.4g", v->number);
    case LU_JSON_STRING: return g_strdup(v->text);
    case LU_JSON_BOOL: return g_strdup(v->boolean ? "true" : "false");
    default: return g_strdup("null");
    }
}

/* What the value is compared with: the paper's number, else lamina's own
 * reference (an exact solution, our FEM; issue 16 item 2). */
static const lu_json *target(const lu_json *e)
{
    const lu_json *p = lu_json_get(e, "paper");
    return p ? p : lu_json_get(e, "ref");
}

/* Within tolerance of the paper (or of our reference when the paper gives
 * none): 1, outside: 0, not comparable: -1. The one rule behind the pages'
 * marks and `gallery --check`'s coverage rule (gallery_coverage.c). */
int g_value_check(const lu_json *e)
{
    const lu_json *v = lu_json_get(e, "value"), *p = target(e), *t = lu_json_get(e, "tol");
    if (!v || !p || !t || v->type != LU_JSON_NUMBER || p->type != LU_JSON_NUMBER ||
        t->type != LU_JSON_NUMBER)
        return -1;
    return fabs(v->number - p->number) <= t->number;
}

/* "✓", "✗" or "" for g_value_check's 1, 0, -1. */
static const char *mark(const lu_json *e)
{
    int c = g_value_check(e);
    return c < 0 ? "" : c ? " ✓" : " ✗";
}

/* "name: 0.27 % (paper 0.3 ± 0.05 %) ✓", or "(ours 0.3 ± 0.05 %)" for a
 * reference of lamina's own */
char *g_value_line(const lu_json *e)
{
    const char *unit = lu_json_string(e, "unit");
    int is_paper = lu_json_get(e, "paper") != NULL;
    char *v = show(lu_json_get(e, "value")), *p = show(target(e)),
         *t = show(lu_json_get(e, "tol"));
    const char *name = lu_json_string(e, "name");
    char *paper = p ? g_fmt(" (%s %s%s%s%s%s)", is_paper ? "paper" : "ours", p,
                            t ? " ± " : "", t ? t : "", unit ? " " : "", unit ? unit : "")
                    : g_strdup("");
    char *line = g_fmt("%s: %s%s%s%s%s", name ? name : "?", v ? v : "?", unit ? " " : "",
                       unit ? unit : "", paper, mark(e));
    free(v);
    free(p);
    free(t);
    free(paper);
    return line;
}

static const lu_json *values_of(const lu_json *meta)
{
    const lu_json *v = lu_json_get(meta, "values");
    return v && v->type == LU_JSON_ARRAY ? v : NULL;
}

/* A figure's values, one line each, through put (Markdown or HTML). */
static void put_values(FILE *f, const lu_json *meta, void (*put)(FILE *, const char *))
{
    const lu_json *vals = values_of(meta);
    for (size_t k = 0; vals && k < vals->n; k++) {
        char *line = g_value_line(&vals->kids[k]);
        if (k)
            fputs("<br>", f);
        put(f, line);
        free(line);
    }
}

static char *run_time(const lu_json *meta)
{
    if (!meta)
        return g_strdup("not rendered yet");
    double status = lu_json_number(meta, "status", -1);
    if (status != 0)
        return g_fmt("failed (exit %g)", status);
    double s = lu_json_number(meta, "seconds", 0);
    return s < 60 ? g_fmt("%.1f s", s) : g_fmt("%.0f min %.0f s", floor(s / 60),
                                               fmod(s, 60));
}

/* ---- the page of one figure -------------------------------------------- */

static void page_field(FILE *f, const char *heading, const char *text)
{
    if (text && *text) {
        fprintf(f, "\n## %s\n\n", heading);
        g_markdown_text(f, text);
        fputc('\n', f);
    }
}

int g_write_page(const g_options *o, const g_script *s, const lu_json *meta, char *err,
                 size_t errlen)
{
    char *dir = g_fmt("%s/%s", o->gallery, s->stem);
    char *path = g_fmt("%s/%s", dir, G_PAGE);
    char *rel = g_relpath(dir, s->path);
    char *rt = run_time(meta);
    g_text t;
    g_text_open(&t);
    FILE *f = t.f;
    fprintf(f, "<!-- written by `lamina gallery` from %s.lua: edit the script, not "
               "this page (docs/gallery.md) -->\n\n", s->stem);
    fputs("# ", f);
    g_markdown_text(f, s->h.title ? s->h.title : s->stem);
    fputs("\n\n", f);
    if (s->h.source) {
        fputs("**Source:** ", f);
        g_markdown_text(f, s->h.source);
        fputs("\n\n", f);
    }
    fprintf(f, "**Script:** [`%s.lua`](%s) · lamina %s · run time %s\n\n", s->stem,
            rel ? rel : s->path, lu_json_string(meta, "version") ? lu_json_string(meta, "version")
                                                              : LAMINA_VERSION, rt);
    if (s->h.heavy)
        fprintf(f, "**Heavy:** %s — rendered by `lamina gallery --heavy` (or `--only %s`), "
                   "not by a plain `lamina gallery`\n\n", s->h.heavy, s->stem);
    char *thumb = g_fmt("%s/%s", dir, G_THUMB);
    if (g_exists(thumb))
        fprintf(f, "![%s](%s)\n", s->stem, G_THUMB);
    free(thumb);
    page_field(f, "What to look for", s->h.look);
    page_field(f, "What was assumed", s->h.assumed);
    page_field(f, "Numbers it checks", s->h.checks);

    const lu_json *vals = values_of(meta);
    if (vals && vals->n) {
        fputs("\n## Measured\n\n\"Paper\" is a number the paper prints; \"Ours\" a "
              "reference lamina computes itself (an exact solution, our FEM, p r / t of the "
              "same run). The tolerance applies to the paper's number, else to ours.\n\n"
              "| Quantity | Measured | Paper | Ours | Tolerance | Unit | |\n"
              "| --- | --- | --- | --- | --- | --- | --- |\n", f);
        for (size_t i = 0; i < vals->n; i++) {
            const lu_json *e = &vals->kids[i];
            char *v = show(lu_json_get(e, "value")), *p = show(lu_json_get(e, "paper")),
                 *ref = show(lu_json_get(e, "ref")), *tol = show(lu_json_get(e, "tol"));
            fputs("| ", f);
            g_markdown_cell(f, lu_json_string(e, "name"));
            fputs(" | ", f);
            g_markdown_cell(f, v);
            fputs(" | ", f);
            g_markdown_cell(f, p ? p : "");
            fputs(" | ", f);
            g_markdown_cell(f, ref ? ref : "");
            fputs(" | ", f);
            g_markdown_cell(f, tol ? tol : "");
            fputs(" | ", f);
            g_markdown_cell(f, lu_json_string(e, "unit"));
            fprintf(f, " |%s |\n", mark(e));
            free(v);
            free(p);
            free(ref);
            free(tol);
        }
    }

    const lu_json *imgs = lu_json_get(meta, "images"), *data = lu_json_get(meta, "data");
    if (imgs && imgs->type == LU_JSON_ARRAY && imgs->n) {
        fputs("\n## Images\n\nFull size, as the script wrote them. They are not committed "
              "(`gallery/.gitignore`): run `lamina gallery` to see them here.\n", f);
        for (size_t i = 0; i < imgs->n; i++)
            if (imgs->kids[i].type == LU_JSON_STRING)
                fprintf(f, "\n### %s\n\n![%s](%s)\n", imgs->kids[i].text,
                        imgs->kids[i].text, imgs->kids[i].text);
    }
    if (data && data->type == LU_JSON_ARRAY && data->n) {
        fputs("\n## Data\n\n", f);
        for (size_t i = 0; i < data->n; i++)
            if (data->kids[i].type == LU_JSON_STRING)
                fprintf(f, "- [%s](%s)\n", data->kids[i].text, data->kids[i].text);
    }
    if (meta && lu_json_number(meta, "status", -1) != 0)
        fprintf(f, "\n## The last run failed\n\nExit status %g; its output is in "
                   "[`%s`](%s).\n", lu_json_number(meta, "status", -1), G_LOG, G_LOG);
    g_text_close(&t);
    int rc = g_write_file(path, t.buf, t.len, err, errlen);
    free(t.buf);
    free(rt);
    free(rel);
    free(path);
    free(dir);
    return rc;
}

/* ---- the index ---------------------------------------------------------- */

typedef struct row {
    const g_script *s;
    lu_json *meta;
    int has_thumb;
} row;

static void index_markdown(FILE *f, const g_options *o, const row *rows, size_t n)
{
    fputs("<!-- written by `lamina gallery`: edit the scripts, not this file "
          "(docs/gallery.md) -->\n\n# Gallery\n\n", f);
    fprintf(f, "Every reproduced figure, made again from its script in `%s/` by "
               "`lamina gallery`. A thumbnail leads to the figure's page: what to look "
               "for, the numbers measured beside the paper's, the full-size images. "
               "How to add a figure: `docs/gallery.md`. The same "
               "figures as a grid of cards, each with at most three headline checks: "
               "[index.html](index.html).\n\n", o->scripts);
    if (n == 0) {
        fprintf(f, "No figures yet: `%s/` has no scripts.\n", o->scripts);
        return;
    }
    fputs("| Figure | Title | Source | Measured vs paper (or ours) | Run time |\n"
          "| --- | --- | --- | --- | --- |\n", f);
    for (size_t i = 0; i < n; i++) {
        const g_script *s = rows[i].s;
        if (rows[i].has_thumb) {
            fputs("| [![", f);
            markdown_name(f, s->stem);
            fputs("](", f);
            g_url(f, s->stem);
            fprintf(f, "/%s)](", G_THUMB);
            g_url(f, s->stem);
            fprintf(f, "/%s) | ", G_PAGE);
        } else {
            fputs("| — | ", f);
        }
        fputc('[', f);
        if (s->h.title) g_markdown_cell(f, s->h.title);
        else markdown_name(f, s->stem);
        fputs("](", f);
        g_url(f, s->stem);
        fprintf(f, "/%s) | ", G_PAGE);
        g_markdown_cell(f, s->h.source ? s->h.source : "");
        fputs(" | ", f);
        put_values(f, rows[i].meta, g_markdown_cell);
        char *rt = run_time(rows[i].meta);
        fprintf(f, " | %s |\n", rt);
        free(rt);
    }
    g_coverage_markdown(f, o);
}

/* ---- the web page: a grid of cards ------------------------------------ */

#define HEADLINES 3

/* The values a card shows (issue 32 item 9: at most three, the full list
 * on the figure's page): first those beside the paper's number with a
 * tolerance (a ✓ or ✗), then those beside lamina's own reference with one,
 * then the paper's numbers without; each pass in the report's order. */
static size_t headlines(const lu_json *meta, const lu_json *out[HEADLINES])
{
    const lu_json *vals = values_of(meta);
    size_t n = 0;
    for (int pass = 0; pass < 3 && vals; pass++)
        for (size_t k = 0; k < vals->n && n < HEADLINES; k++) {
            const lu_json *e = &vals->kids[k];
            int paper = lu_json_get(e, "paper") != NULL, ref = lu_json_get(e, "ref") != NULL;
            int tol = lu_json_get(e, "tol") != NULL;
            if ((pass == 0 && paper && tol) || (pass == 1 && !paper && ref && tol) ||
                (pass == 2 && paper && !tol))
                out[n++] = e;
        }
    return n;
}

/* One headline: name (its unit as the tooltip), the paper's number (or
 * "ours" and lamina's reference) with its tolerance, lamina's value, the
 * mark. */
static void headline_row(FILE *f, const lu_json *e)
{
    int is_paper = lu_json_get(e, "paper") != NULL;
    char *v = show(lu_json_get(e, "value")), *p = show(target(e)),
         *t = show(lu_json_get(e, "tol"));
    const char *m = mark(e);
    fputs("<tr><td", f);
    const char *unit = lu_json_string(e, "unit");
    if (unit) {
        fputs(" title=\"", f);
        g_html(f, unit);
        fputc('"', f);
    }
    fputc('>', f);
    g_html(f, lu_json_string(e, "name"));
    fputs("</td><td>", f);
    if (!is_paper)
        fputs("ours ", f);
    g_html(f, p);
    if (t) {
        fputs(" ± ", f);
        g_html(f, t);
    }
    fputs("</td><td>", f);
    g_html(f, v);
    fprintf(f, "</td><td class=\"%s\">%s</td></tr>\n",
            strstr(m, "✓") ? "ok" : strstr(m, "✗") ? "miss" : "", m);
    free(v);
    free(p);
    free(t);
}

/* <a href="STEM/README.md">: a script's name, whatever it holds, goes into
 * the attribute percent-encoded (issue 31: a file name was HTML injection). */
static void page_link(FILE *f, const char *stem)
{
    fputs("<a href=\"", f);
    g_url(f, stem);
    fprintf(f, "/%s\">", G_PAGE);
}

static void card(FILE *f, const row *r)
{
    const g_script *s = r->s;
    fputs("<div class=\"card\">\n", f);
    if (r->has_thumb) {
        page_link(f, s->stem);
        fputs("<img src=\"", f);
        g_url(f, s->stem);
        fprintf(f, "/%s\" alt=\"", G_THUMB);
        g_html(f, s->stem);
        fputs("\"></a>\n", f);
    } else {
        fputs("<div class=\"nothumb\">not rendered yet</div>\n", f);
    }
    fputs("<h2>", f);
    page_link(f, s->stem);
    g_html(f, s->h.title ? s->h.title : s->stem);
    fputs("</a></h2>\n<p class=\"src\">", f);
    g_html(f, s->h.source);
    fputs("</p>\n", f);
    const lu_json *h[HEADLINES];
    size_t nh = headlines(r->meta, h);
    if (nh) {
        fputs("<table class=\"checks\">\n<tr><th>check</th><th>paper</th>"
              "<th>lamina</th><th></th></tr>\n", f);
        for (size_t i = 0; i < nh; i++)
            headline_row(f, h[i]);
        fputs("</table>\n", f);
    }
    const lu_json *vals = values_of(r->meta);
    size_t nv = vals ? vals->n : 0;
    /* no run time here (the page has it): the card stays the same from
     * run to run, so its screenshot can be compared */
    fputs("<p class=\"more\">", f);
    page_link(f, s->stem);
    if (nv > nh && nv > 1)
        fprintf(f, "all %zu values", nv);
    else
        fputs("the page", f);
    fputs("</a></p>\n</div>\n", f);
}

/* A grid of cards as sphinx-gallery's and raylib's example indexes are
 * (issue 32 item 9): thumbnail, title, source, at most three headline
 * checks; it wraps to the window and fits 1400 px without scrolling
 * sideways (tests/visual/index_*.sh screenshots it). */
static void index_html(FILE *f, const g_options *o, const row *rows, size_t n)
{
    fputs("<!DOCTYPE html>\n<!-- written by `lamina gallery`: edit the scripts, not this "
          "file (docs/gallery.md) -->\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
          "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
          "<title>lamina gallery</title>\n<style>\n"
          "body { font-family: sans-serif; margin: 1.5em; color: #222; "
          "overflow-wrap: anywhere; }\n"
          ".grid { display: grid; grid-template-columns: repeat(auto-fill, minmax(280px, 1fr)); "
          "gap: 14px; }\n"
          ".card { border: 1px solid #ccc; border-radius: 4px; padding: 8px; min-width: 0; }\n"
          ".card img { display: block; max-width: 100%; height: auto; margin: 0 auto; }\n"
          ".nothumb { height: 120px; background: #f4f4f4; color: #888; text-align: center; "
          "line-height: 120px; }\n"
          ".card h2 { font-size: 1em; margin: 8px 0 4px; }\n"
          ".card h2 a { color: #124; text-decoration: none; }\n"
          ".src { font-size: 0.8em; color: #555; margin: 0 0 6px; }\n"
          ".checks { width: 100%; border-collapse: collapse; font-size: 0.78em; "
          "table-layout: fixed; }\n"
          ".checks th, .checks td { border-top: 1px solid #e4e4e4; padding: 2px 3px; "
          "text-align: left; vertical-align: top; }\n"
          ".checks th { color: #666; font-weight: normal; }\n"
          ".checks th:nth-child(1) { width: 42%; } .checks th:nth-child(2) { width: 30%; }\n"
          ".checks th:nth-child(4) { width: 1.2em; }\n"
          "td.ok { color: #1a7f37; } td.miss { color: #c62828; font-weight: bold; }\n"
          ".more { font-size: 0.78em; color: #666; margin: 6px 0 0; }\n"
          "table { border-collapse: collapse; max-width: 100%; }\n"
          "th, td { border: 1px solid #ccc; padding: 4px 8px; vertical-align: top; "
          "text-align: left; }\n"
          "th { background: #f4f4f4; }\n"
          ".checks th { background: none; border-left: 0; border-right: 0; "
          "border-bottom: 0; }\n"
          ".checks td { border-left: 0; border-right: 0; border-bottom: 0; }\n"
          "td.num { white-space: nowrap; }\n"
          "</style>\n</head>\n<body>\n<h1>lamina gallery</h1>\n", f);
    /* the scripts' folder is not named here (README.md names it): the page
     * then does not depend on where the checkout lies, and its screenshot
     * can be compared anywhere */
    fputs("<p>Every reproduced figure, made again from its script by <code>lamina "
          "gallery</code>. A thumbnail leads to the figure's page: "
          "what to look for and every number measured (<a href=\"README.md\">README.md</a> "
          "lists them all for GitHub). A card shows at most three: the paper's number (or "
          "lamina's own reference), lamina's, ✓ within the stated tolerance, ✗ outside; "
          "hover a name for its unit.</p>\n", f);
    if (n == 0) {
        fputs("<p>No figures yet: <code>", f);
        g_html(f, o->scripts);
        fputs("/</code> has no scripts.</p>\n</body>\n</html>\n", f);
        return;
    }
    fputs("<div class=\"grid\">\n", f);
    for (size_t i = 0; i < n; i++)
        card(f, &rows[i]);
    fputs("</div>\n", f);
    g_coverage_html(f, o);
    fputs("</body>\n</html>\n", f);
}

int g_write_index(const g_options *o, const g_scripts *all, char *err, size_t errlen)
{
    row *rows = g_alloc((all->n ? all->n : 1) * sizeof *rows);
    for (size_t i = 0; i < all->n; i++) {
        const g_script *s = &all->v[i];
        char *meta = g_fmt("%s/%s/%s", o->gallery, s->stem, G_META);
        char *thumb = g_fmt("%s/%s/%s", o->gallery, s->stem, G_THUMB);
        rows[i].s = s;
        rows[i].meta = g_exists(meta) ? gj_read(meta, NULL, 0) : NULL;
        rows[i].has_thumb = g_exists(thumb);
        free(meta);
        free(thumb);
    }
    g_text md, html;
    g_text_open(&md);
    index_markdown(md.f, o, rows, all->n);
    g_text_close(&md);
    g_text_open(&html);
    index_html(html.f, o, rows, all->n);
    g_text_close(&html);
    char *pmd = g_fmt("%s/%s", o->gallery, G_PAGE);
    char *phtml = g_fmt("%s/index.html", o->gallery);
    int rc = g_write_file(pmd, md.buf, md.len, err, errlen);
    if (rc == 0)
        rc = g_write_file(phtml, html.buf, html.len, err, errlen);
    free(pmd);
    free(phtml);
    free(md.buf);
    free(html.buf);
    for (size_t i = 0; i < all->n; i++)
        lu_json_free(rows[i].meta);
    free(rows);
    return rc;
}
