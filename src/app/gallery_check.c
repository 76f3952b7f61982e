/* gallery_check.c - `lamina gallery --check`: does gallery/ agree with the
 * scripts? Runs no simulation, so CI can afford it on every push:
 *
 *   - every script has a header (title, source, look) and a gallery folder
 *     with its page, thumbnail and meta.json, from a successful run of the
 *     script as it is now (the script hash in meta.json);
 *   - no gallery folder is left without its script;
 *   - the index exists in both forms and lists every figure, and every link
 *     in it points at a file that exists;
 *   - the papers' coverage (SCRIPTS/coverage.tsv, gallery_coverage.c) names
 *     only pages that exist, names every page, and gives each page the
 *     figures its source header cites, and no row marked reproduced names
 *     a page with a failing check; the index shows it as it is now.
 *
 * Exit 0 when all holds, 1 with the list of problems otherwise. */
#include "gallery.h"

#include "render.h"

#include <fnmatch.h>
#include <stdlib.h>
#include <string.h>

static void problem(g_strs *p, char *owned)
{
    g_strs_add(p, owned);
}

static void check_figure(const g_options *o, const g_script *s, g_strs *p)
{
    if (!s->h.title || !s->h.source || !s->h.look)
        problem(p, g_fmt("%s: the header lacks%s%s%s", s->path,
                         s->h.title ? "" : " '-- title:'",
                         s->h.source ? "" : " '-- source:'", s->h.look ? "" : " '-- look:'"));
    char *dir = g_fmt("%s/%s", o->gallery, s->stem);
    if (!g_is_dir(dir)) {
        problem(p, g_fmt("%s: no gallery folder %s/ (run: lamina gallery --only %s)",
                         s->path, dir, s->stem));
        free(dir);
        return;
    }
    char *page = g_fmt("%s/%s", dir, G_PAGE), *thumb = g_fmt("%s/%s", dir, G_THUMB),
         *meta = g_fmt("%s/%s", dir, G_META);
    if (!g_exists(page))
        problem(p, g_fmt("%s: missing its page", page));
    char err[512];
    lu_json *m = g_exists(meta) ? gj_read(meta, err, sizeof err) : NULL;
    if (!g_exists(meta))
        problem(p, g_fmt("%s: missing (the record of the last run)", meta));
    else if (!m)
        problem(p, g_fmt("%s", err));
    if (m && lu_json_number(m, "status", -1) != 0)
        problem(p, g_fmt("%s: the last run failed (exit status %g; see %s/%s)", s->stem,
                         lu_json_number(m, "status", -1), dir, G_LOG));
    else if (m && (!lu_json_string(m, "script_hash") ||
                   strcmp(lu_json_string(m, "script_hash"), s->script_hash) != 0))
        problem(p, g_fmt("%s: changed since its figure was made (run: lamina gallery "
                         "--only %s)", s->path, s->stem));
    if (!g_exists(thumb)) {
        problem(p, g_fmt("%s: missing its thumbnail (does the script write a PNG into "
                         "its 'out' folder?)", thumb));
    } else {
        int w, h;
        unsigned char *px;
        if (lr_png_read(thumb, &w, &h, &px, err, sizeof err) != 0)
            problem(p, g_fmt("%s", err));
        else
            free(px);
    }
    lu_json_free(m);
    free(page);
    free(thumb);
    free(meta);
    free(dir);
}

/* The relative link targets in text: Markdown "](target)" and HTML
 * href="target" / src="target". External and in-page links are skipped. */
static void links(const char *text, g_strs *out)
{
    static const char *const openers[] = { "](", "href=\"", "src=\"" };
    static const char closers[] = { ')', '"', '"' };
    for (int k = 0; k < 3; k++) {
        for (const char *q = strstr(text, openers[k]); q; q = strstr(q, openers[k])) {
            q += strlen(openers[k]);
            size_t n = strcspn(q, k ? "\"" : ")");
            if (q[n] != closers[k])
                break;
            char *t = g_fmt("%.*s", (int)n, q);
            t[strcspn(t, "#?")] = '\0';
            if (!*t || strstr(t, "://") || !strncmp(t, "mailto:", 7))
                free(t);
            else
                g_strs_add(out, t);
        }
    }
}

static int hex(char c)
{
    return c >= '0' && c <= '9' ? c - '0' : c >= 'A' && c <= 'F' ? c - 'A' + 10
         : c >= 'a' && c <= 'f' ? c - 'a' + 10 : -1;
}

/* %XX sequences of a link into their bytes, in place. */
static void url_decode(char *s)
{
    char *w = s;
    for (const char *r = s; *r; r++) {
        if (r[0] == '%' && hex(r[1]) >= 0 && hex(r[2]) >= 0) {
            *w++ = (char)(hex(r[1]) * 16 + hex(r[2]));
            r += 2;
        } else {
            *w++ = *r;
        }
    }
    *w = '\0';
}

static void check_index(const g_options *o, const char *name, const g_scripts *all,
                        void (*coverage)(FILE *, const g_options *), g_strs *p)
{
    char *path = g_fmt("%s/%s", o->gallery, name);
    char *text;
    if (g_read_file(path, &text, NULL, NULL, 0) != 0) {
        problem(p, g_fmt("%s: missing (run: lamina gallery)", path));
        free(path);
        return;
    }
    g_strs l = { 0 };
    links(text, &l);
    for (size_t i = 0; i < l.n; i++) {
        url_decode(l.v[i]);   /* the index percent-encodes names (g_url) */
        char *target = l.v[i][0] == '/' ? g_strdup(l.v[i])
                                         : g_fmt("%s/%s", o->gallery, l.v[i]);
        if (!g_exists(target))
            problem(p, g_fmt("%s links to %s, which does not exist", path, l.v[i]));
        free(target);
    }
    for (size_t i = 0; i < all->n; i++) {
        char *want = g_fmt("%s/%s", all->v[i].stem, G_PAGE);   /* links decoded above */
        int found = 0;
        for (size_t k = 0; k < l.n && !found; k++)
            found = strcmp(l.v[k], want) == 0;
        if (!found)
            problem(p, g_fmt("%s does not list %s (run: lamina gallery)", path,
                             all->v[i].stem));
        free(want);
    }
    g_strs_free(&l);
    g_text cov;                      /* the coverage section as it would be written now */
    g_text_open(&cov);
    coverage(cov.f, o);
    g_text_close(&cov);
    if (cov.len && !strstr(text, cov.buf))
        problem(p, g_fmt("%s: its coverage section is not %s/%s as it is now (run: lamina "
                         "gallery)", path, o->scripts, G_COVERAGE));
    free(cov.buf);
    free(text);
    free(path);
}

int g_check(const g_options *o)
{
    char err[1024];
    g_scripts all;
    if (g_find_scripts(o->scripts, NULL, &all, err, sizeof err) != 0) {
        fprintf(stderr, "lamina gallery --check: %s\n", err);
        return 2;
    }
    g_strs p = { 0 };
    if (!g_is_dir(o->gallery))
        problem(&p, g_fmt("%s: the gallery folder does not exist (run: lamina gallery)",
                          o->gallery));
    size_t checked = 0;
    for (size_t i = 0; i < all.n; i++) {
        if (o->only && fnmatch(o->only, all.v[i].stem, 0) != 0)
            continue;
        check_figure(o, &all.v[i], &p);
        checked++;
    }
    g_strs dirs = { 0 };
    if (g_list_dirs(o->gallery, &dirs, err, sizeof err) != 0)
        problem(&p, g_strdup(err));
    for (size_t i = 0; i < dirs.n; i++) {
        int known = 0;
        for (size_t k = 0; k < all.n && !known; k++)
            known = strcmp(all.v[k].stem, dirs.v[i]) == 0;
        if (!known)
            problem(&p, g_fmt("%s/%s/: no script %s/%s.lua made it (remove the folder)",
                              o->gallery, dirs.v[i], o->scripts, dirs.v[i]));
    }
    g_coverage_check(o, &all, &p);
    if (g_is_dir(o->gallery)) {
        check_index(o, G_PAGE, &all, g_coverage_markdown, &p);
        check_index(o, "index.html", &all, g_coverage_html, &p);
    }
    for (size_t i = 0; i < p.n; i++)
        fprintf(stderr, "gallery check: %s\n", p.v[i]);
    if (p.n)
        fprintf(stderr, "gallery check: %zu problem%s in %s/ (docs/gallery.md)\n", p.n,
                p.n == 1 ? "" : "s", o->gallery);
    else if (!o->quiet)
        printf("gallery check: %s/ agrees with %s/: %zu figure%s checked, index links "
               "resolve\n", o->gallery, o->scripts, checked, checked == 1 ? "" : "s");
    int rc = p.n ? 1 : 0;
    g_strs_free(&p);
    g_strs_free(&dirs);
    g_scripts_free(&all);
    return rc;
}
