#!/bin/sh
# Sweeps on real schedulers (issue 20 item 4): the --emit-jobs lines run
# unchanged under GNU parallel (Debian `parallel`, installed by
# .ci/setup.sh) and --collect summarises them; --slurm FILE writes an
# sbatch script with --array over the runs and FILE.jobs, whose array tasks
# run here by hand (SLURM_ARRAY_TASK_ID) and then collect the same; where
# Slurm is installed, `sbatch --test-only` checks the script, else that
# check is skipped with a message.
. "$(dirname "$0")/lib.sh"
command -v parallel >/dev/null || { echo "FAIL: GNU parallel is not installed (.ci/setup.sh installs it)"; exit 1; }

"$LAMINA" sweep "$SRC/disks.lua" --set E=1000,2000,3000 --out par --emit-jobs > jobs.txt 2> err.txt \
  || { echo "FAIL: --emit-jobs"; fail=1; }
parallel --will-cite -j 2 < jobs.txt > parallel.out 2> parallel.err
status=$?
[ $status -eq 0 ] || { echo "FAIL: GNU parallel exited with $status"; fail=1; }
"$LAMINA" sweep --collect par > collect.out 2> collect.err
status=$?
[ $status -eq 0 ] || { echo "FAIL: --collect after GNU parallel: exit $status"; fail=1; }
check collect.err "^sweep: 3 runs, 0 failed"
check par/summary.csv "^E=1000,1000,0,"
check par/summary.csv "^E=3000,3000,0,"

"$LAMINA" sweep "$SRC/disks.lua" --set E=1000,2000 --out slurm_runs --slurm array.sbatch \
  > slurm.out 2> slurm.err || { echo "FAIL: --slurm"; fail=1; }
check array.sbatch "^#SBATCH --array=0-1$"
check array.sbatch "^#SBATCH --output=/.*/slurm_runs/slurm-%A_%a.out$"
[ "$(wc -l < array.sbatch.jobs)" -eq 2 ] || { echo "FAIL: array.sbatch.jobs is not 2 lines"; fail=1; }
bash -n array.sbatch || { echo "FAIL: array.sbatch is not valid bash"; fail=1; }
[ ! -e slurm_runs/E=1000 ] || { echo "FAIL: --slurm ran something"; fail=1; }
mkdir elsewhere
for k in 0 1; do
  (cd elsewhere && SLURM_ARRAY_TASK_ID=$k bash ../array.sbatch > ../task$k.out 2> ../task$k.err) \
    || { echo "FAIL: array task $k"; fail=1; }
done
SLURM_ARRAY_TASK_ID=5 bash array.sbatch > task5.out 2> task5.err
[ $? -eq 2 ] || { echo "FAIL: a task past the array's end must fail"; fail=1; }
check task5.err "no job 5 in"
"$LAMINA" sweep --collect slurm_runs > collect2.out 2> collect2.err
[ $? -eq 0 ] || { echo "FAIL: --collect after the array tasks"; fail=1; }
check collect2.err "^sweep: 2 runs, 0 failed"
if command -v sbatch >/dev/null; then
  sbatch --test-only array.sbatch > sbatch.out 2>&1 || { echo "FAIL: sbatch --test-only"; cat sbatch.out; fail=1; }
else
  echo "sweep_scheduler: Slurm is not installed here: sbatch --test-only skipped"
fi
[ $fail -eq 0 ] || show jobs.txt parallel.err collect.err array.sbatch task0.err collect2.err
[ $fail -eq 0 ] && echo "sweep_scheduler: 3 runs through GNU parallel and 2 Slurm array tasks collected"
exit $fail
