/* gallery_visual.c - visual regression: `lamina gallery --compare` and
 * `--update-baselines`.
 *
 * For each figure script: run it (with the header's `-- visual:` settings,
 * which make it small and quick) into --work, make the thumbnail of its key
 * image - the candidate - and compare it with BASELINES/<stem>.png by
 * lr_diff. A script that reports `state_hash` (sim:hash()) is also held to
 * BASELINES/<stem>.hash, which tells the two kinds of change apart: a new
 * picture with the old state hash is a drawing change, a new state hash is
 * a simulation change.
 *
 * --compare never rewrites a baseline, except a missing one: it fails and
 * writes the candidate where the baseline belongs, to be looked at and
 * committed. A failure leaves expected.png, actual.png, diff.png and
 * report.html in WORK/<stem>/. --update-baselines rewrites exactly the
 * baselines that fail (or are missing) and leaves the others' bytes alone. */
#include "gallery.h"

#include "diff.h"
#include "render.h"

#include <stdlib.h>
#include <string.h>

enum hash_state { HASH_NONE, HASH_SAME, HASH_CHANGED, HASH_NO_BASELINE };

typedef struct outcome {
    int ran;                    /* the script ran and wrote an image */
    int missing;                /* no baseline image */
    int image_same;
    int hash;                   /* enum hash_state */
    char state_hash[65];        /* reported by the script (a longer one is refused) */
    char base_hash[65];         /* in the baseline */
    char summary[1024];         /* the diff's summary line, or what went wrong */
} outcome;

static int passes(const outcome *c)
{
    return c->ran && !c->missing && c->image_same && c->hash != HASH_CHANGED &&
           c->hash != HASH_NO_BASELINE;
}

/* The reported `state_hash` value, if any. */
static void reported_hash(const char *report, outcome *c)
{
    lu_json *r = gj_read(report, NULL, 0);
    const lu_json *vals = lu_json_get(r, "values");
    for (size_t i = 0; vals && vals->type == LU_JSON_ARRAY && i < vals->n; i++) {
        const char *name = lu_json_string(&vals->kids[i], "name");
        const char *v = lu_json_string(&vals->kids[i], "value");
        if (name && v && !strcmp(name, "state_hash")) {
            /* whole or not at all: a hash cut short would compare equal
             * where the state changed */
            if (strlen(v) < sizeof c->state_hash)
                snprintf(c->state_hash, sizeof c->state_hash, "%s", v);
            else
                snprintf(c->state_hash, sizeof c->state_hash, "(state_hash longer than %d characters)",
                         (int)sizeof c->state_hash - 30);
        }
    }
    lu_json_free(r);
}

static void baseline_hash(const char *path, outcome *c)
{
    if (!c->state_hash[0])
        return;
    char *text;
    if (g_read_file(path, &text, NULL, NULL, 0) != 0) {
        c->hash = HASH_NO_BASELINE;
        return;
    }
    snprintf(c->base_hash, sizeof c->base_hash, "%.*s", (int)strcspn(text, " \t\r\n"), text);
    free(text);
    c->hash = strcmp(c->base_hash, c->state_hash) ? HASH_CHANGED : HASH_SAME;
}

/* What the state hash says, in words. */
static void hash_words(const outcome *c, char *buf, size_t len)
{
    switch (c->hash) {
    case HASH_SAME:
        snprintf(buf, len, c->image_same ? "the simulation state is unchanged (state hash "
                                           "%s)"
                                         : "only the drawing changed: the simulation state "
                                           "hash %s is the baseline's", c->state_hash);
        break;
    case HASH_CHANGED:
        snprintf(buf, len, "the simulation changed: state hash %s, baseline %s%s",
                 c->state_hash, c->base_hash,
                 c->image_same ? " (the picture did not change visibly)" : "");
        break;
    case HASH_NO_BASELINE:
        snprintf(buf, len, "no state hash baseline yet (state hash %s)", c->state_hash);
        break;
    default:
        snprintf(buf, len, "the script reports no state_hash, so a simulation change "
                           "cannot be told from a drawing change");
    }
}

static void img_cell(FILE *f, const char *name, int w)
{
    int shown = w > 0 && w <= 400 ? 2 * w : w;
    fprintf(f, "<td><a href=\"%s\"><img src=\"%s\" alt=\"%s\"", name, name, name);
    if (shown > 0)
        fprintf(f, " width=\"%d\"", shown);
    fputs("></a></td>", f);
}

static int write_report(const g_options *o, const g_script *s, const char *wdir,
                        const char *baseline, const outcome *c, const char *hash_text)
{
    char *actual = g_fmt("%s/actual.png", wdir);
    int w = 0, h = 0;
    unsigned char *px = NULL;
    if (lr_png_read(actual, &w, &h, &px, NULL, 0) == 0)
        free(px);
    g_text t;
    g_text_open(&t);
    FILE *f = t.f;
    fputs("<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>"
          "visual regression: ", f);
    g_html(f, s->stem);
    fputs("</title>\n<style>\nbody { font-family: sans-serif; margin: 2em; color: #222; }\n"
          "img { border: 1px solid #999; image-rendering: pixelated; }\n"
          "th, td { text-align: left; vertical-align: top; padding: 0 1em 0.5em 0; }\n"
          "code { background: #f4f4f4; padding: 1px 3px; }\n</style>\n</head>\n<body>\n<h1>",
          f);
    g_html(f, s->stem);
    fputs(c->missing ? ": no baseline" : ": different", f);
    fputs("</h1>\n<p>", f);
    g_html(f, c->summary);
    fputs("</p>\n<p>", f);
    g_html(f, hash_text);
    fputs("</p>\n<table>\n<tr><th>expected (baseline)</th><th>actual</th>"
          "<th>diff: red differs, yellow is anti-aliasing, grey unchanged</th></tr>\n<tr>", f);
    char *exp = g_fmt("%s/expected.png", wdir), *dif = g_fmt("%s/diff.png", wdir);
    if (g_exists(exp)) img_cell(f, "expected.png", w); else fputs("<td>(none)</td>", f);
    img_cell(f, "actual.png", w);
    if (g_exists(dif)) img_cell(f, "diff.png", w); else fputs("<td>(none)</td>", f);
    fputs("</tr>\n</table>\n<p>Baseline: <code>", f);
    g_html(f, baseline);
    fputs("</code>. Script: <code>", f);
    g_html(f, s->path);
    if (s->h.visual) {
        fputs("</code>, run with <code>", f);
        g_html(f, s->h.visual);
    }
    for (int i = 0; i < o->nsets; i++) {
        fputs(i ? " " : "</code> and <code>", f);
        g_html(f, o->sets[i]);
    }
    fputs("</code>. The run's output: <a href=\"log.txt\">log.txt</a>.</p>\n"
          "<p>If the new picture is right, accept it with<br><code>lamina gallery "
          "--update-baselines --only ", f);
    g_html(f, s->stem);
    fputs(" --scripts ", f);
    g_html(f, o->scripts);
    fputs(" --baselines ", f);
    g_html(f, o->baselines);
    fputs("</code></p>\n</body>\n</html>\n", f);
    g_text_close(&t);
    char *path = g_fmt("%s/report.html", wdir);
    char err[512];
    int rc = g_write_file(path, t.buf, t.len, err, sizeof err);
    if (rc != 0)
        fprintf(stderr, "lamina gallery: %s\n", err);
    free(t.buf);
    free(path);
    free(exp);
    free(dif);
    free(actual);
    return rc;
}

/* Makes the candidate: runs the script into wdir/run and thumbnails its key
 * image into wdir/actual.png. */
static int candidate(const g_options *o, const g_script *s, const char *wdir, outcome *c)
{
    char err[1024];
    char *run = g_fmt("%s/run", wdir), *report = g_fmt("%s/%s", wdir, G_REPORT),
         *log = g_fmt("%s/%s", wdir, G_LOG), *actual = g_fmt("%s/actual.png", wdir);
    g_strs sets = { 0 }, images = { 0 };
    g_visual_sets(s, &sets);
    for (int i = 0; i < o->nsets; i++)
        g_strs_add(&sets, g_strdup(o->sets[i]));
    g_run_result r = { 0 };
    int rc = -1;
    if (g_clear_dir(wdir, err, sizeof err) || g_mkdirs(run, err, sizeof err) ||
        g_run(s, run, report, log, (const char *const *)sets.v, (int)sets.n, &r, err,
              sizeof err)) {
        snprintf(c->summary, sizeof c->summary, "%s", err);
    } else if (r.status != 0 && r.timed_out) {
        snprintf(c->summary, sizeof c->summary, "the script was stopped after the time "
                 "limit of %g s (--timeout S); the end of %s:", g_run_limit(), log);
    } else if (r.status != 0) {
        snprintf(c->summary, sizeof c->summary, "the script failed (lamina run exit "
                 "status %d); the end of %s:", r.status, log);
    } else if (g_outputs(run, &images, NULL, err, sizeof err)) {
        snprintf(c->summary, sizeof c->summary, "%s", err);
    } else if (!images.n) {
        snprintf(c->summary, sizeof c->summary, "the script wrote no image into its 'out' "
                 "folder");
    } else {
        char *src = g_fmt("%s/%s", run, g_key_image(s, &images));
        rc = g_thumbnail(src, actual, G_THUMB_WIDTH, err, sizeof err);
        if (rc != 0)
            snprintf(c->summary, sizeof c->summary, "%s", err);
        free(src);
        reported_hash(report, c);
    }
    c->ran = rc == 0;
    if (!c->ran) {
        fprintf(stderr, "visual: %s: FAILED: %s\n", s->stem, c->summary);
        if (r.status != 0)
            g_show_log_tail(log, 6);
    }
    g_strs_free(&sets);
    g_strs_free(&images);
    free(run);
    free(report);
    free(log);
    free(actual);
    return rc;
}

static void compare(const char *baseline, const char *hashfile, const char *wdir,
                    outcome *c)
{
    char *actual = g_fmt("%s/actual.png", wdir), *diff = g_fmt("%s/diff.png", wdir);
    if (!g_exists(baseline)) {
        c->missing = 1;
        snprintf(c->summary, sizeof c->summary, "no baseline %s", baseline);
    } else {
        lr_diff_opts opts;
        lr_diff_defaults(&opts);
        lr_diff_result res;
        char err[1024];
        if (lr_diff_files(baseline, actual, &opts, diff, &res, err, sizeof err) != 0) {
            snprintf(c->summary, sizeof c->summary, "%s", err);
        } else {
            c->image_same = res.same;
            lr_diff_summary(&res, &opts, c->summary, sizeof c->summary);
        }
    }
    baseline_hash(hashfile, c);
    free(actual);
    free(diff);
}

/* Writes the candidate (and its state hash) as the baseline; a picture
 * that passed keeps its bytes when only the hash is new. */
static int accept(const char *wdir, const char *baseline, const char *hashfile,
                  const outcome *c)
{
    char err[1024];
    char *actual = g_fmt("%s/actual.png", wdir);
    int rc = c->missing || !c->image_same ? g_copy_file(actual, baseline, err, sizeof err)
                                          : 0;
    if (rc == 0 && c->state_hash[0]) {
        char *line = g_fmt("%s\n", c->state_hash);
        rc = g_write_file(hashfile, line, strlen(line), err, sizeof err);
        free(line);
    }
    if (rc != 0)
        fprintf(stderr, "lamina gallery: %s\n", err);
    free(actual);
    return rc;
}

/* 0 passes, 1 fails (or was rewritten in update mode: *rewritten = 1). */
static int visual_one(const g_options *o, const g_script *s, int *rewritten)
{
    outcome c;
    memset(&c, 0, sizeof c);
    char *wdir = g_fmt("%s/%s", o->work, s->stem);
    char *baseline = g_fmt("%s/%s.png", o->baselines, s->stem);
    char *hashfile = g_fmt("%s/%s.hash", o->baselines, s->stem);
    int rc = 1;
    if (candidate(o, s, wdir, &c) == 0) {
        compare(baseline, hashfile, wdir, &c);
        char words[512];
        hash_words(&c, words, sizeof words);
        if (passes(&c)) {
            rc = 0;
            if (!o->quiet)
                printf("visual: %s: %s; %s\n", s->stem, c.summary, words);
        } else if (o->update) {
            if (accept(wdir, baseline, hashfile, &c) == 0) {
                *rewritten = 1;
                rc = 0;
                printf("visual: %s: %s (%s; %s)\n", s->stem,
                       c.missing ? "baseline created"
                       : c.image_same ? "state hash baseline rewritten, picture kept"
                                      : "baseline rewritten", c.summary, words);
            }
        } else if ((c.missing || c.hash == HASH_NO_BASELINE) && o->nsets) {
            /* a changed scene (a negative control) must never become a baseline */
            fprintf(stderr, "visual: %s: FAILED: no baseline %s (not written: this run "
                    "has --set changes)\n", s->stem, c.missing ? baseline : hashfile);
        } else if (c.missing || c.hash == HASH_NO_BASELINE) {
            /* the candidate goes where the baseline belongs, to be reviewed */
            if (accept(wdir, baseline, hashfile, &c) == 0)
                fprintf(stderr, "visual: %s: FAILED: no baseline; wrote the candidate to "
                        "%s%s - look at it, and commit it if it is right\n", s->stem,
                        c.missing ? baseline : hashfile,
                        c.missing && c.state_hash[0] ? " (and its .hash)" : "");
        } else {
            char err[512];
            char *expected = g_fmt("%s/expected.png", wdir);
            if (g_copy_file(baseline, expected, err, sizeof err) != 0)
                fprintf(stderr, "lamina gallery: %s\n", err);
            write_report(o, s, wdir, baseline, &c, words);
            char *report = g_fmt("%s/report.html", wdir);
            char *abs = g_abspath(report);
            fprintf(stderr, "visual: %s: FAILED: %s; %s\n  report: %s\n", s->stem, c.summary,
                    words, abs);
            free(abs);
            free(report);
            free(expected);
        }
    }
    free(wdir);
    free(baseline);
    free(hashfile);
    return rc;
}

int g_visual(const g_options *o)
{
    char err[1024];
    g_scripts chosen;
    if (g_find_scripts(o->scripts, o->only, &chosen, err, sizeof err) != 0) {
        fprintf(stderr, "lamina gallery: %s\n", err);
        return 2;
    }
    if (o->only && chosen.n == 0) {
        fprintf(stderr, "lamina gallery: no script in '%s' matches --only '%s'\n",
                o->scripts, o->only);
        g_scripts_free(&chosen);
        return 2;
    }
    size_t failed = 0, rewritten = 0;
    for (size_t i = 0; i < chosen.n; i++) {
        int rw = 0;
        failed += visual_one(o, &chosen.v[i], &rw) != 0;
        rewritten += (size_t)rw;
    }
    if (o->update)
        printf("visual: %zu baseline%s checked, %zu rewritten, %zu could not be made\n",
               chosen.n, chosen.n == 1 ? "" : "s", rewritten, failed);
    else if (!o->quiet || failed)
        printf("visual: %zu compared: %zu same, %zu failed\n", chosen.n, chosen.n - failed,
               failed);
    g_scripts_free(&chosen);
    return failed ? 1 : 0;
}
