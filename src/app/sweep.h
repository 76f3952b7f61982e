/* sweep.h - `lamina sweep`: many independent runs of one scenario and a
 * table of what they reported (docs/workbench.md). */
#ifndef LAMINA_SWEEP_H
#define LAMINA_SWEEP_H

#include <stddef.h>
#include <stdio.h>
#include <sys/types.h>

/* The files of one run's folder. */
#define SW_RECORD "run.txt"       /* parameters, exit status, wall time */
#define SW_STDOUT "stdout.txt"
#define SW_STDERR "stderr.txt"    /* the run log: errors, live changes, progress */
#define SW_REPORT "report.json"   /* lamina run --report */

typedef struct sw_set {
    const char *name, *value;
} sw_set;

/* One run: `lamina run SCRIPT --set ...` in its own folder. */
typedef struct sw_job {
    char *folder;        /* absolute */
    sw_set *sets;
    int nsets;
    pid_t pid;
    double start, wall;
    char status[32];     /* "0".."255", "signal N" */
    int ok;
} sw_job;

/* What every run shares. */
typedef struct sw_context {
    char exe[4096];      /* this program, from /proc/self/exe */
    char script[4096];   /* absolute */
    int add_out;         /* pass --set out=FOLDER (the script reads param "out") */
    int quiet;           /* pass --quiet */
} sw_context;

/* sweep_job.c */
/* 0, or -1 with a message: exe and the script's absolute path. */
int sw_context_init(sw_context *c, const char *script, int user_sets_out, int quiet);
/* mkdir -p; 0 or -1 (errno). */
int sw_mkdirs(const char *path);
/* Creates the folder, records the run and starts it; 0 or -1 (message). */
int sw_job_start(const sw_context *c, sw_job *job);
/* Records how the run ended (wstatus from waitpid). */
void sw_job_finish(const sw_context *c, sw_job *job, int wstatus);
/* The run as one shell command line (what --emit-jobs prints). */
void sw_job_print_command(FILE *out, const sw_context *c, const sw_job *job);
/* sweep_slurm.c: PATH (an sbatch script, --array over the runs) and
 * PATH.jobs (their commands); 0, or -1 with a message on stderr. */
int sw_write_slurm(const char *path, const sw_context *c, const sw_job *jobs, int njobs,
                   const char *outdir);
/* Writes s quoted for a POSIX shell. */
void sw_shell_quote(FILE *out, const char *s);
/* A name for a shell line: no control character, and no quote unless
 * quotes (0, or -1 with the message on stderr); sw_check_jobs checks every
 * name of the jobs (file names without quotes, --set values with). */
int sw_shell_safe(const char *what, const char *s, int quotes);
int sw_check_jobs(const sw_context *c, const sw_job *jobs, int njobs);

/* sweep_json.c: the values of a report.json (lamina.report): 0 and n
 * name/value pairs (numbers as written, strings unquoted), or -1. */
int sw_report_read(const char *path, char ***names, char ***values, int *n);

/* sweep_summary.c */
typedef struct sw_row {
    char *label;         /* the folder's name */
    int nparams;
    char **pnames, **pvalues;
    char status[32];     /* exit status, "signal N" or "unfinished" */
    int ok;
    double wall;         /* < 0: unknown */
    int nrep;
    char **rnames, **rvalues;
    char *error;         /* the first error line of a failed run */
} sw_row;

/* sweep_index.c: names (borrowed, they must outlive it) to positions. put
 * keeps the first position of a name; get gives -1 for a name not put. */
typedef struct sw_index {
    const char **key;
    int *val;
    size_t cap, n;
} sw_index;
int sw_index_put(sw_index *ix, const char *key, int val);   /* 0, or -1: out of memory */
int sw_index_get(const sw_index *ix, const char *key);
void sw_index_free(sw_index *ix);

/* Loads a run folder; 0, or -1 when it holds no run record. */
int sw_row_load(const char *folder, sw_row *row);
void sw_row_free(sw_row *row);
/* Sorts rows by their parameters (numbers as numbers). */
void sw_rows_sort(sw_row *rows, int n);
/* Writes DIR/summary.csv and DIR/summary.md and prints the table on out;
 * 0 or -1 with a message. */
int sw_summary_write(const char *dir, const char *title, sw_row *rows, int n, FILE *out);

#endif
