/* sweep_slurm.c - `lamina sweep ... --slurm FILE`: the sweep as a Slurm job
 * array (docs/workbench.md).
 *
 * Writes FILE.jobs, the commands --emit-jobs prints (one per run, each a
 * complete shell line), and FILE, an sbatch script whose array task k runs
 * line k + 1 of it. Nothing runs here; `sbatch FILE` submits, and
 * `lamina sweep --collect OUTDIR` builds the summary afterwards. The array
 * task can also be run by hand, `SLURM_ARRAY_TASK_ID=0 bash FILE`, which is
 * how the tests check the script where Slurm is not installed. */
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "atomic_file.h"
#include "sweep.h"

/* #SBATCH lines cannot be quoted: the folder's name must be plain. */
static int plain_path(const char *s)
{
    for (; *s; s++)
        if (!((*s >= 'a' && *s <= 'z') || (*s >= 'A' && *s <= 'Z') || (*s >= '0' && *s <= '9') ||
              strchr("/._+-=,", *s)))
            return 0;
    return 1;
}

int sw_write_slurm(const char *path, const sw_context *c, const sw_job *jobs, int njobs,
                   const char *outdir)
{
    char err[PATH_MAX + 200], jobs_path[PATH_MAX];
    if (sw_shell_safe("--slurm", path, 0)) return -1;
    if (!plain_path(outdir)) {
        fprintf(stderr, "lamina sweep: --slurm: the output folder '%s' has characters an "
                "#SBATCH line cannot carry (use letters, digits and /._+-=,)\n", outdir);
        return -1;
    }
    if (snprintf(jobs_path, sizeof jobs_path, "%s.jobs", path) >= (int)sizeof jobs_path) {
        fprintf(stderr, "lamina sweep: --slurm: '%s' is too long\n", path);
        return -1;
    }
    /* the array tasks may start in another folder: the jobs file by its
     * absolute path */
    char cwd[PATH_MAX], jobs_abs[PATH_MAX * 2];
    if (!getcwd(cwd, sizeof cwd)) {
        fprintf(stderr, "lamina sweep: --slurm: the working folder is unknown\n");
        return -1;
    }
    snprintf(jobs_abs, sizeof jobs_abs, "%s%s%s", jobs_path[0] == '/' ? "" : cwd,
             jobs_path[0] == '/' ? "" : "/", jobs_path);

    if (sw_shell_safe("the jobs file", jobs_abs, 0)) return -1;
    lr_atomic a;
    if (lr_atomic_open(&a, jobs_path, err, sizeof err)) goto fail;
    for (int i = 0; i < njobs; i++) sw_job_print_command(a.fp, c, &jobs[i]);
    if (lr_atomic_commit(&a, err, sizeof err)) goto fail;

    if (sw_mkdirs(outdir) != 0) {
        fprintf(stderr, "lamina sweep: --slurm: cannot make '%s'\n", outdir);
        return -1;
    }
    if (lr_atomic_open(&a, path, err, sizeof err)) goto fail;
    fprintf(a.fp,
            "#!/bin/bash\n"
            "# A lamina sweep as a Slurm job array, written by `lamina sweep --slurm`:\n"
            "# %d run%s of %s. Submit with `sbatch %s`; when the array has finished,\n"
            "# `lamina sweep --collect %s` writes summary.md and summary.csv.\n"
            "# Array task k runs line k + 1 of the jobs file (the commands\n"
            "# --emit-jobs prints); by hand: SLURM_ARRAY_TASK_ID=0 bash %s\n"
            "#SBATCH --job-name=lamina-sweep\n"
            "#SBATCH --array=0-%d\n"
            "#SBATCH --ntasks=1\n"
            "#SBATCH --cpus-per-task=1\n"
            "#SBATCH --output=%s/slurm-%%A_%%a.out\n"
            "set -eu\n"
            "JOBS=", njobs, njobs == 1 ? "" : "s", c->script, path, outdir, path,
            njobs - 1, outdir);
    sw_shell_quote(a.fp, jobs_abs);
    fputs("\n"
          "task=${SLURM_ARRAY_TASK_ID:?not a Slurm array task (set SLURM_ARRAY_TASK_ID)}\n"
          "line=$(sed -n \"$((task + 1))p\" \"$JOBS\")\n"
          "if [ -z \"$line\" ]; then echo \"no job $task in $JOBS\" >&2; exit 2; fi\n"
          "eval \"$line\"\n", a.fp);
    if (lr_atomic_commit(&a, err, sizeof err)) goto fail;
    fprintf(stderr, "sweep: %d run%s as a Slurm array in %s (commands in %s); submit with "
            "sbatch %s\n", njobs, njobs == 1 ? "" : "s", path, jobs_path, path);
    return 0;
fail:
    fprintf(stderr, "lamina sweep: --slurm: %s\n", err);
    return -1;
}
