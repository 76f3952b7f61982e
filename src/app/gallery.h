/* gallery.h - `lamina gallery`, one job per file:
 *
 *   cmd_gallery.c     the command line; the default mode (render stale figures)
 *   gallery_fs.c      files: read, atomic write, mkdir -p, list, remove, copy
 *   gallery_json.c    reading (lu_json_parse) and writing meta.json, report.json
 *   gallery_script.c  finding the scripts, their header comment, their hash
 *   gallery_run.c     one script as a `lamina run` subprocess, timed
 *   gallery_queue.c   several figures' runs at once, the longest first
 *   gallery_thumb.c   box-filtered thumbnails
 *   gallery_index.c   the index (README.md, index.html) and the figure pages
 *   gallery_check.c   --check: the gallery agrees with the scripts
 *   gallery_coverage.c  the papers' figures and tables the gallery covers
 *   gallery_visual.c  --compare / --update-baselines: visual regression
 *
 * Errors are values: functions return 0 or -1 with a message in err[].
 * Running out of memory for a path or a line of text is the one exception:
 * g_fmt and friends print it and exit with status 2, since a command-line
 * tool can do nothing better then. */
#ifndef LAMINA_GALLERY_H
#define LAMINA_GALLERY_H

#include <stddef.h>
#include <stdio.h>

#include "util.h"

#define G_THUMB_WIDTH 256            /* thumbnails and baselines: at most this wide */
#define G_THUMB "thumb.png"          /* per figure: the index's thumbnail */
#define G_PAGE "README.md"           /* per figure: its page */
#define G_META "meta.json"           /* per figure: what the last run made */
#define G_REPORT "report.json"       /* per figure: lamina.report's values */
#define G_LOG "log.txt"              /* per figure: the run's stdout and stderr */
#define G_COVERAGE "coverage.tsv"    /* in the scripts folder: the papers' coverage */

/* ---- options --------------------------------------------------------- */

typedef struct g_options {
    const char *scripts;        /* --scripts DIR (scripts/paper) */
    const char *gallery;        /* --gallery DIR (gallery) */
    const char *baselines;      /* --baselines DIR (tests/visual/baselines) */
    const char *work;           /* --work DIR (out/visual) */
    const char *only;           /* --only PATTERN (a glob on the script's stem) */
    int force, check, compare, update, quiet;
    int heavy;                  /* --heavy: render the pages marked heavy too */
    int jobs;                   /* --jobs N: figures run at once (the cores online) */
    const char **sets;          /* --set name=value, for --compare */
    int nsets;
} g_options;

/* ---- gallery_fs.c ---------------------------------------------------- */

typedef struct g_strs {
    char **v;
    size_t n, cap;
} g_strs;

char *g_fmt(const char *fmt, ...) __attribute__((format(printf, 1, 2)));
char *g_strdup(const char *s);
void *g_alloc(size_t n);                  /* zeroed */
void g_strs_add(g_strs *l, char *owned);
void g_strs_sort(g_strs *l);
void g_strs_free(g_strs *l);

int g_exists(const char *path);
int g_is_dir(const char *path);
int g_read_file(const char *path, char **text, size_t *len, char *err, size_t errlen);
/* Through a temporary beside path, then rename(2); creates missing folders. */
int g_write_file(const char *path, const char *text, size_t len, char *err, size_t errlen);
int g_copy_file(const char *from, const char *to, char *err, size_t errlen);
int g_mkdirs(const char *dir, char *err, size_t errlen);
/* Removes everything inside dir (not dir itself); a missing dir is fine. */
int g_clear_dir(const char *dir, char *err, size_t errlen);
/* Regular files under dir, recursively, as sorted paths relative to dir. */
int g_list_files(const char *dir, g_strs *out, char *err, size_t errlen);
/* Sub-folders of dir (not recursive), sorted names. */
int g_list_dirs(const char *dir, g_strs *out, char *err, size_t errlen);
/* A relative path from folder `from` to `to`, both existing; NULL if not known. */
char *g_relpath(const char *from, const char *to);
/* path made absolute (symbolic links resolved), or a copy of it if it does not exist. */
char *g_abspath(const char *path);
int g_has_suffix(const char *s, const char *suffix);

/* A growing text buffer over open_memstream. */
typedef struct g_text {
    FILE *f;
    char *buf;
    size_t len;
} g_text;
void g_text_open(g_text *t);
/* Closes the stream; t->buf/t->len hold the text (free t->buf). */
void g_text_close(g_text *t);

/* ---- gallery_json.c -------------------------------------------------- */

/* The tree is lu_json (src/util/util.h: lu_json_parse, lu_json_get, ...). */
lu_json *gj_read(const char *path, char *err, size_t errlen);
void gj_put_string(FILE *f, const char *s);
/* Writes v as JSON (objects one member per line at `indent`). */
void gj_put(FILE *f, const lu_json *v, int indent);

/* ---- gallery_script.c ------------------------------------------------ */

typedef struct g_header {
    char *title;    /* -- title: what the figure shows */
    char *source;   /* -- source: paper and figure */
    char *look;     /* -- look: what to look for */
    char *checks;   /* -- checks: the numbers it checks */
    char *assumed;  /* -- assumed: inputs the paper leaves out, and why */
    char *thumb;    /* -- thumb: the image the index shows (default: the last) */
    char *visual;   /* -- visual: name=value ... for the regression run */
    char *heavy;    /* -- heavy: why it is rendered only with --heavy (or --only) */
} g_header;

typedef struct g_script {
    char *stem;                 /* file name without .lua */
    char *path;                 /* scripts dir/stem.lua */
    g_header h;
    char script_hash[17];       /* FNV-1a of the bytes (as in the PNGs' provenance) */
    char hash[17];              /* of the bytes and the program version: staleness */
} g_script;

typedef struct g_scripts {
    g_script *v;
    size_t n;
} g_scripts;

/* The DIR/NAME.lua scripts whose NAME matches `only` (NULL: all), sorted. */
int g_find_scripts(const char *dir, const char *only, g_scripts *out, char *err,
                   size_t errlen);
void g_scripts_free(g_scripts *s);
/* Splits the header's `visual` field into name=value words. */
void g_visual_sets(const g_script *s, g_strs *out);

/* ---- gallery_run.c --------------------------------------------------- */

typedef struct g_run_result {
    int status;         /* lamina run's exit status; 128+N killed by signal N */
    double seconds;     /* wall-clock */
    double cpu_seconds; /* the run's processor time (user + system, all its threads) */
    int timed_out;      /* stopped after the time limit (g_run_set_limit) */
} g_run_result;

/* Each figure's time limit in seconds (lamina gallery --timeout S): an
 * endless loop in a downloaded script must not hang the gallery. */
#define G_RUN_LIMIT 1800.0
void g_run_set_limit(double seconds);
double g_run_limit(void);

/* `lamina run SCRIPT --set out=OUT --report REPORT [--set ...] --quiet`
 * with stdout and stderr into log. */
int g_run(const g_script *s, const char *out, const char *report, const char *log,
          const char *const *sets, int nsets, g_run_result *r, char *err, size_t errlen);
/* The same in two halves, so that several figures can run at once
 * (gallery_queue.c): g_run_start forks the run; g_run_poll returns 0 while
 * it runs (sending the time limit's signals when due), 1 when it ended
 * (r filled), -1 on an error. g_run_nap sleeps between polls (20 ms). */
typedef struct g_child {
    int pid;
    double t0;
    int sent;           /* 0, 1 after SIGTERM, 2 after SIGKILL */
} g_child;
int g_run_start(const g_script *s, const char *out, const char *report, const char *log,
                const char *const *sets, int nsets, g_child *c, char *err, size_t errlen);
int g_run_poll(g_child *c, g_run_result *r, char *err, size_t errlen);
void g_run_nap(void);
/* The last few lines of a log, to stderr, indented. */
void g_show_log_tail(const char *log, int lines);

/* ---- gallery_queue.c ------------------------------------------------- */

/* Figures rendered at once, longest first (LPT: the longest run starts
 * first so that it does not start last and end alone); the light ones
 * fill the other cores meanwhile. Each run's state depends on its
 * script's thread count only (docs/design.md, "Engine"), never on what
 * else runs, so the pages are the same whatever the order. */
typedef struct g_job {
    const g_script *s;
    double cost;        /* the last run's CPU seconds (g_last_cost); < 0 unknown */
    g_child child;
} g_job;

typedef struct g_queue_ops {
    /* 0: started (j->child runs); 1: nothing to wait for (it failed at
     * once: counted as failed); -1: the gallery cannot be written */
    int (*start)(void *ctx, g_job *j);
    /* the run ended (poll_rc 1, r filled) or could not be waited for
     * (poll_rc -1, err): 0 rendered, 1 the run failed, -1 broken */
    int (*finish)(void *ctx, g_job *j, int poll_rc, const g_run_result *r, const char *err);
} g_queue_ops;

/* The figure's last run's cost from its meta.json: "cpu_seconds", else
 * "seconds" (older pages); -1 when there is none. */
double g_last_cost(const char *meta_path);
/* The default of --jobs: the processors online (1 if unknown). */
int g_default_jobs(void);
typedef struct g_queue_stats {
    size_t ran, failed;     /* runs ended, of which failed */
    double cpu;             /* their processor time, summed */
    double wall;            /* from the first start to the last end */
} g_queue_stats;
/* Runs the n jobs, at most max_jobs at once, the costliest first (unknown
 * cost first of all; ties in the given order), counting into st; after a
 * -1 (the gallery cannot be written) starts no more, waits for the running
 * ones, and returns -1; else 0. */
int g_queue_run(g_job *jobs, size_t n, int max_jobs, const g_queue_ops *ops, void *ctx,
                g_queue_stats *st);

/* ---- gallery_thumb.c ------------------------------------------------- */

/* A copy of src at most max_width wide (box filter: each output pixel is
 * the area-weighted mean of what it covers), written to dst as PNG. */
int g_thumbnail(const char *src, const char *dst, int max_width, char *err, size_t errlen);

/* ---- gallery_index.c ------------------------------------------------- */

/* The PNG images and other outputs of a figure folder (reserved names excluded). */
int g_outputs(const char *dir, g_strs *images, g_strs *data, char *err, size_t errlen);
/* The image the index shows: the header's `thumb` if present, else the last. */
const char *g_key_image(const g_script *s, const g_strs *images);
void g_markdown_cell(FILE *f, const char *s);
/* s in Markdown text: no raw HTML tag, no control character but line breaks
 * and tabs (gallery_index.c). */
void g_markdown_text(FILE *f, const char *s);
void g_html(FILE *f, const char *s);
/* s percent-encoded as one URL path segment (all but A-Z a-z 0-9 - . _ ~) */
void g_url(FILE *f, const char *s);
/* A reported value (an element of meta.json's "values") against what it is
 * compared with - the paper's number, else lamina's own reference - and its
 * tolerance: 1 within (the page's ✓), 0 outside (✗, a failing check), -1
 * not comparable (no mark). */
int g_value_check(const lu_json *e);
/* "name: 0.27 % (paper 0.3 ± 0.05 %) ✓" (free it). */
char *g_value_line(const lu_json *e);
int g_write_page(const g_options *o, const g_script *s, const lu_json *meta, char *err,
                 size_t errlen);
int g_write_index(const g_options *o, const g_scripts *all, char *err, size_t errlen);

/* ---- gallery_coverage.c ---------------------------------------------- */

/* The figures and tables a source header cites, as "T Fig 31", "F Table IV":
 * a paper is named by "1999" / "(membranes)" / "[M]", "2000" /
 * "(fluid-membrane)" / "[F]", "normals paper" / "[N]", "dissertation" /
 * "[T]", and holds until another is named. */
void g_source_refs(const char *source, g_strs *out);
/* Problems of SCRIPTS/coverage.tsv against the scripts and, for the rows
 * marked reproduced, against their pages' checks in GALLERY/NAME/meta.json,
 * added to problems (none when the file does not exist). */
void g_coverage_check(const g_options *o, const g_scripts *all, g_strs *problems);
/* The coverage section of the index (nothing when there is no data). */
void g_coverage_markdown(FILE *f, const g_options *o);
void g_coverage_html(FILE *f, const g_options *o);

/* ---- modes ----------------------------------------------------------- */

int g_check(const g_options *o);       /* gallery_check.c */
int g_visual(const g_options *o);      /* gallery_visual.c */

#endif
