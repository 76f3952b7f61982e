/* cmd_gallery.c - `lamina gallery`: the command line, and its default mode,
 * which renders every stale figure script into gallery/ and rewrites the
 * index.
 *
 * A figure is stale when its meta.json is missing, records a failed run, or
 * holds another hash of (script bytes, program version), or when a file it
 * lists is gone (a fresh clone has the pages but not the full-size images).
 * --force renders all. One figure failing does not stop the others; the
 * exit status is 1 then. */
#include <stdlib.h>
#include <string.h>

#include "app.h"
#include "gallery.h"

static const char usage_text[] =
    "usage: lamina gallery [--only PATTERN] [--force] [--heavy] [--check] [--compare]\n"
    "                      [--update-baselines] [--scripts DIR] [--gallery DIR]\n"
    "                      [--baselines DIR] [--work DIR] [--set name=value] [--jobs N]\n"
    "                      [--timeout S] [--quiet]\n"
    "  (no mode)           render the stale scripts/paper/*.lua into gallery/, write the index\n"
    "  --check             verify gallery/ against the scripts, running nothing\n"
    "  --compare           visual regression: render small candidates into --work and\n"
    "                      compare them with the baselines\n"
    "  --update-baselines  the same, then rewrite only the baselines that failed\n"
    "  --only PATTERN      only scripts whose name (without .lua) matches the glob\n"
    "  --force             render even figures that are up to date\n"
    "  --heavy             render the figures marked heavy too (else only with --only)\n"
    "  --scripts DIR       the figure scripts (scripts/paper)\n"
    "  --gallery DIR       the gallery (gallery)\n"
    "  --baselines DIR     the baseline images (tests/visual/baselines)\n"
    "  --work DIR          candidates and failure reports (out/visual)\n"
    "  --set name=value    passed to every run (--compare only; for negative controls)\n"
    "  --jobs N            figures rendered at once, the longest first (the cores online)\n"
    "  --timeout S         each figure's time limit in seconds (1800)\n"
    "See docs/gallery.md.\n";

static int usage_error(const char *fmt, const char *arg)
{
    fputs("lamina gallery: ", stderr);
    fprintf(stderr, fmt, arg);
    fprintf(stderr, "\n%s", usage_text);
    return -1;
}

/* "--name value" or "--name=value" */
static int take(int argc, char **argv, int *i, const char *name, const char **out)
{
    const char *v;
    if (!lu_opt_value(argc, argv, i, name, &v))
        return 0;
    if (!v || !*v)
        return usage_error("%s needs a value", name);
    *out = v;
    return 1;
}

static int parse_args(int argc, char **argv, g_options *o)
{
    int jobs_given = 0;
    for (int i = 0; i < argc; i++) {
        const char *a = argv[i], *set = NULL;
        int r;
        if ((r = take(argc, argv, &i, "--only", &o->only)) ||
            (r = take(argc, argv, &i, "--scripts", &o->scripts)) ||
            (r = take(argc, argv, &i, "--gallery", &o->gallery)) ||
            (r = take(argc, argv, &i, "--baselines", &o->baselines)) ||
            (r = take(argc, argv, &i, "--work", &o->work))) {
            if (r < 0)
                return -1;
        } else if ((r = take(argc, argv, &i, "--timeout", &set))) {
            if (r < 0)
                return -1;
            char *end;
            double t = strtod(set, &end);
            if (*end || !(t >= 1 && t <= 604800))
                return usage_error("--timeout needs seconds from 1 to 604800 (got '%s')", set);
            g_run_set_limit(t);
        } else if ((r = take(argc, argv, &i, "--jobs", &set))) {
            if (r < 0)
                return -1;
            char *end;
            long n = strtol(set, &end, 10);
            if (*end || n < 1 || n > 64)
                return usage_error("--jobs needs a whole number from 1 to 64 (got '%s')", set);
            o->jobs = (int)n;
            jobs_given = 1;
        } else if ((r = take(argc, argv, &i, "--set", &set))) {
            if (r < 0)
                return -1;
            if (!strchr(set, '=') || set[0] == '=')
                return usage_error("--set needs name=value (got '%s')", set);
            o->sets[o->nsets++] = set;
        } else if (!strcmp(a, "--force")) {
            o->force = 1;
        } else if (!strcmp(a, "--heavy")) {
            o->heavy = 1;
        } else if (!strcmp(a, "--check")) {
            o->check = 1;
        } else if (!strcmp(a, "--compare")) {
            o->compare = 1;
        } else if (!strcmp(a, "--update-baselines")) {
            o->update = 1;
        } else if (!strcmp(a, "--quiet") || !strcmp(a, "-q")) {
            o->quiet = 1;
        } else if (a[0] == '-') {
            return usage_error("unknown option '%s'", a);
        } else {
            return usage_error("unexpected argument '%s' (scripts are found in --scripts DIR)",
                               a);
        }
    }
    if (o->check + o->compare + o->update > 1)
        return usage_error("%s", "--check, --compare and --update-baselines exclude each other");
    if (o->force && (o->check || o->compare || o->update))
        return usage_error("%s", "--force is for rendering the gallery only");
    if (jobs_given && (o->check || o->compare || o->update))
        return usage_error("%s", "--jobs is for rendering the gallery only (--check, --compare "
                                 "and --update-baselines run one figure at a time)");
    if (o->nsets && !o->compare)
        return usage_error("%s", "--set is for --compare only (a gallery figure is what "
                                 "its script makes)");
    return 0;
}

/* ---- rendering one figure ---------------------------------------------- */

static void put_strs(FILE *f, const char *key, const g_strs *l)
{
    fprintf(f, "  \"%s\": [", key);
    for (size_t i = 0; i < l->n; i++) {
        fputs(i ? ", " : "", f);
        gj_put_string(f, l->v[i]);
    }
    fputs("],\n", f);
}

static void put_opt_string(FILE *f, const char *key, const char *v)
{
    fprintf(f, "  \"%s\": ", key);
    if (v)
        gj_put_string(f, v);
    else
        fputs("null", f);
    fputs(",\n", f);
}

/* meta.json: what the page and the index are written from, and what makes
 * a figure up to date. */
static int write_meta(const char *path, const g_script *s, const g_run_result *r,
                      const char *key, int has_thumb, const g_strs *images,
                      const g_strs *data, const lu_json *report, char *err, size_t errlen)
{
    g_text t;
    g_text_open(&t);
    FILE *f = t.f;
    fputs("{\n", f);
    put_opt_string(f, "stem", s->stem);
    put_opt_string(f, "title", s->h.title);
    put_opt_string(f, "version", LAMINA_VERSION);
    put_opt_string(f, "script_hash", s->script_hash);
    put_opt_string(f, "hash", s->hash);
    fprintf(f, "  \"status\": %d,\n  \"seconds\": %.3f,\n  \"cpu_seconds\": %.3f,\n", r->status,
            r->seconds, r->cpu_seconds);
    put_opt_string(f, "key_image", key);
    put_opt_string(f, "thumb", has_thumb ? G_THUMB : NULL);
    put_strs(f, "images", images);
    put_strs(f, "data", data);
    const lu_json *values = lu_json_get(report, "values");
    fputs("  \"values\": ", f);
    if (values && values->type == LU_JSON_ARRAY)
        gj_put(f, values, 2);
    else
        fputs("[]", f);
    fputs("\n}\n", f);
    g_text_close(&t);
    int rc = g_write_file(path, t.buf, t.len, err, errlen);
    free(t.buf);
    return rc;
}

static int up_to_date(const g_options *o, const g_script *s)
{
    char *dir = g_fmt("%s/%s", o->gallery, s->stem);
    char *path = g_fmt("%s/%s", dir, G_META);
    lu_json *meta = gj_read(path, NULL, 0);
    int ok = meta && lu_json_string(meta, "hash") && !strcmp(lu_json_string(meta, "hash"), s->hash) &&
             lu_json_number(meta, "status", -1) == 0;
    char *page = g_fmt("%s/%s", dir, G_PAGE);
    ok = ok && g_exists(page);
    free(page);
    const lu_json *imgs = lu_json_get(meta, "images");
    for (size_t i = 0; ok && imgs && i < imgs->n; i++) {
        char *p = g_fmt("%s/%s", dir, imgs->kids[i].text ? imgs->kids[i].text : "");
        ok = g_exists(p);
        free(p);
    }
    if (ok && lu_json_string(meta, "thumb")) {
        char *p = g_fmt("%s/%s", dir, G_THUMB);
        ok = g_exists(p);
        free(p);
    }
    lu_json_free(meta);
    free(path);
    free(dir);
    return ok;
}

/* An up-to-date figure's page, written again from its meta.json and the
 * script's header: a page is a function of the two, so a change of how
 * pages are written (or of a header's text) reaches every page without
 * running the scripts again. 0, or -1 with the error printed. */
static int refresh_page(const g_options *o, const g_script *s)
{
    char err[1024];
    char *path = g_fmt("%s/%s/%s", o->gallery, s->stem, G_META);
    lu_json *m = gj_read(path, err, sizeof err);
    int rc = m ? g_write_page(o, s, m, err, sizeof err) : -1;
    if (rc != 0) fprintf(stderr, "lamina gallery: %s: %s\n", s->stem, err);
    lu_json_free(m);
    free(path);
    return rc;
}

/* The files of one figure's folder in the gallery, named once for the
 * start and the end of its run (g_fmt exits on no memory). */
enum { FIG_DIR, FIG_REPORT, FIG_LOG, FIG_META, FIG_THUMB, FIG_NPATHS };

typedef struct fig_paths {
    char *p[FIG_NPATHS];        /* p[FIG_DIR] the folder, the rest in it */
} fig_paths;

static fig_paths fig_paths_of(const g_options *o, const g_script *s)
{
    static const char *const name[FIG_NPATHS] = {NULL, G_REPORT, G_LOG, G_META, G_THUMB};
    fig_paths f;
    f.p[FIG_DIR] = g_fmt("%s/%s", o->gallery, s->stem);
    for (int k = FIG_DIR + 1; k < FIG_NPATHS; k++)
        f.p[k] = g_fmt("%s/%s", f.p[FIG_DIR], name[k]);
    return f;
}

static void fig_paths_free(fig_paths *f)
{
    for (int k = 0; k < FIG_NPATHS; k++)
        free(f->p[k]);
}

/* The run of one figure started (gallery_queue.c): 0, or -1 (the gallery
 * could not be written) with the error printed. */
static int render_start(void *ctx, g_job *j)
{
    const g_options *o = ctx;
    const g_script *s = j->s;
    char err[1024];
    fig_paths f = fig_paths_of(o, s);
    /* a fresh folder: a frame the script no longer writes must not linger */
    const char *dir = f.p[FIG_DIR];
    int rc = g_clear_dir(dir, err, sizeof err) != 0 || g_mkdirs(dir, err, sizeof err) != 0 ||
                     g_run_start(s, dir, f.p[FIG_REPORT], f.p[FIG_LOG], NULL, 0, &j->child, err,
                                 sizeof err) != 0
                 ? -1
                 : 0;
    if (rc < 0)
        fprintf(stderr, "lamina gallery: %s: %s\n", s->stem, err);
    fig_paths_free(&f);
    return rc;
}

/* The figure's run ended: its thumbnail, meta.json and page. 0 rendered,
 * 1 the run failed, -1 the gallery could not be written. */
static int render_finish(void *ctx, g_job *j, int poll_rc, const g_run_result *rr,
                         const char *run_err)
{
    const g_options *o = ctx;
    const g_script *s = j->s;
    char err[1024];
    fig_paths f = fig_paths_of(o, s);
    const char *dir = f.p[FIG_DIR], *report = f.p[FIG_REPORT], *log = f.p[FIG_LOG];
    const char *meta = f.p[FIG_META], *thumb = f.p[FIG_THUMB];
    g_strs images = { 0 }, data = { 0 };
    lu_json *rep = NULL;
    g_run_result r = *rr;
    int rc = -1;
    snprintf(err, sizeof err, "%s", run_err ? run_err : "");
    if (poll_rc < 0 || g_outputs(dir, &images, &data, err, sizeof err) != 0)
        goto done;
    const char *key = r.status == 0 ? g_key_image(s, &images) : NULL;
    if (key) {
        char *src = g_fmt("%s/%s", dir, key);
        int t = g_thumbnail(src, thumb, G_THUMB_WIDTH, err, sizeof err);
        free(src);
        if (t != 0)
            goto done;
    }
    if (g_exists(report)) {
        rep = gj_read(report, err, sizeof err);
        if (!rep)
            fprintf(stderr, "lamina gallery: %s: %s (numbers left out)\n", s->stem, err);
    }
    if (write_meta(meta, s, &r, key, key != NULL, &images, &data, rep, err, sizeof err))
        goto done;
    lu_json *m = gj_read(meta, err, sizeof err);
    if (!m)
        goto done;
    int p = g_write_page(o, s, m, err, sizeof err);
    lu_json_free(m);
    if (p != 0)
        goto done;
    const lu_json *vals = lu_json_get(rep, "values");
    if (r.status == 0) {
        if (!o->quiet)
            printf("gallery: %s: %.1f s, %zu image%s, %zu value%s%s\n", s->stem, r.seconds,
                   images.n, images.n == 1 ? "" : "s", vals ? vals->n : 0,
                   vals && vals->n == 1 ? "" : "s", key ? "" : " (no image: no thumbnail)");
        rc = 0;
    } else {
        if (r.timed_out)
            fprintf(stderr, "gallery: %s: FAILED: stopped after the time limit of %g s "
                            "(--timeout S); the end of %s:\n", s->stem, g_run_limit(), log);
        else
            fprintf(stderr, "gallery: %s: FAILED (lamina run exit status %d) after %.1f s; "
                            "the end of %s:\n", s->stem, r.status, r.seconds, log);
        g_show_log_tail(log, 6);
        rc = 1;
    }
done:
    if (rc < 0)
        fprintf(stderr, "lamina gallery: %s: %s\n", s->stem, err);
    lu_json_free(rep);
    g_strs_free(&images);
    g_strs_free(&data);
    fig_paths_free(&f);
    return rc;
}

static int render_all(const g_options *o)
{
    char err[1024];
    g_scripts all, chosen;
    if (g_find_scripts(o->scripts, NULL, &all, err, sizeof err) != 0) {
        fprintf(stderr, "lamina gallery: %s\n", err);
        return 2;
    }
    if (g_find_scripts(o->scripts, o->only, &chosen, err, sizeof err) != 0) {
        fprintf(stderr, "lamina gallery: %s\n", err);
        g_scripts_free(&all);
        return 2;
    }
    if (o->only && chosen.n == 0) {
        fprintf(stderr, "lamina gallery: no script in '%s' matches --only '%s'\n",
                o->scripts, o->only);
        g_scripts_free(&all);
        g_scripts_free(&chosen);
        return 2;
    }
    size_t ran = 0, fresh = 0, failed = 0, heavy = 0, njobs = 0;
    int broken = 0;
    g_job *jobs = g_alloc((chosen.n ? chosen.n : 1) * sizeof *jobs);
    for (size_t i = 0; i < chosen.n && !broken; i++) {
        const g_script *s = &chosen.v[i];
        if (!s->h.title || !s->h.source || !s->h.look)
            fprintf(stderr, "lamina gallery: %s: the header lacks%s%s%s (docs/gallery.md)\n",
                    s->path, s->h.title ? "" : " '-- title:'",
                    s->h.source ? "" : " '-- source:'", s->h.look ? "" : " '-- look:'");
        if (s->h.heavy && !o->heavy && !o->only && !up_to_date(o, s)) {
            /* the finest meshes, minutes each (docs/gallery.md "Heavy
             * figures"): the committed page stays, rewritten from its meta */
            heavy++;
            if (!o->quiet)
                printf("gallery: %s: heavy, not rendered (lamina gallery --heavy, or --only %s): "
                       "%s\n", s->stem, s->stem, s->h.heavy);
            char *meta = g_fmt("%s/%s/%s", o->gallery, s->stem, G_META);
            broken = g_exists(meta) && refresh_page(o, s) != 0;
            free(meta);
            continue;
        }
        if (s->h.heavy && !o->heavy && !o->only) {   /* up to date: nothing to run */
            fresh++;
            broken = refresh_page(o, s) != 0;
            continue;
        }
        if (!o->force && up_to_date(o, s)) {
            fresh++;
            if (!o->quiet)
                printf("gallery: %s: up to date\n", s->stem);
            broken = refresh_page(o, s) != 0;
            continue;
        }
        jobs[njobs].s = s;
        char *meta = g_fmt("%s/%s/%s", o->gallery, s->stem, G_META);
        jobs[njobs++].cost = g_last_cost(meta);   /* before its folder is cleared */
        free(meta);
    }
    /* the stale figures, several at once (gallery_queue.c) */
    if (!broken && njobs) {
        static const g_queue_ops ops = { render_start, render_finish };
        g_queue_stats st = { 0 };
        broken = g_queue_run(jobs, njobs, o->jobs, &ops, (void *)o, &st) != 0;
        ran += st.ran;
        failed += st.failed;
        if (!o->quiet)
            printf("gallery: %zu run%s: %.1f s of processor time in %.1f s, up to %d at once\n",
                   st.ran, st.ran == 1 ? "" : "s", st.cpu, st.wall, o->jobs);
    }
    free(jobs);
    if (!broken && g_write_index(o, &all, err, sizeof err) != 0) {
        fprintf(stderr, "lamina gallery: %s\n", err);
        broken = 1;
    }
    if (!o->quiet && !broken)
        printf("gallery: %zu figure%s: %zu rendered, %zu up to date, %zu heavy not rendered, "
               "%zu failed; index: %s/%s and %s/index.html\n", all.n, all.n == 1 ? "" : "s",
               ran - failed, fresh, heavy, failed, o->gallery, G_PAGE, o->gallery);
    g_scripts_free(&all);
    g_scripts_free(&chosen);
    return broken ? 2 : failed ? 1 : 0;
}

int cmd_gallery(int argc, char **argv)
{
    g_options o;
    memset(&o, 0, sizeof o);
    o.scripts = "scripts/paper";
    o.gallery = "gallery";
    o.baselines = "tests/visual/baselines";
    o.work = "out/visual";
    o.jobs = g_default_jobs();
    o.sets = calloc((size_t)argc + 1, sizeof *o.sets);
    if (!o.sets)
        return 2;
    int rc;
    if (parse_args(argc, argv, &o) != 0)
        rc = 2;
    else if (o.check)
        rc = g_check(&o);
    else if (o.compare || o.update)
        rc = g_visual(&o);
    else
        rc = render_all(&o);
    free(o.sets);
    return rc;
}
