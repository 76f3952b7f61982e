#!/bin/sh
# lamina sweep: four runs of the product, two at a time, each in its own
# folder with its output and log; one fails (E < 0) and is reported with
# its status and first error line without stopping the others; the
# summary lists what each run reported.
. "$(dirname "$0")/lib.sh"
"$LAMINA" sweep "$SRC/disks.lua" --set E=1000,2000,-5 --set t_end=0.1,0.2 --set fail=no \
  --jobs 2 --out runs > out.txt 2> err.txt
status=$?
[ $status -eq 1 ] || { echo "FAIL: exit status $status, expected 1 (a run failed)"; fail=1; }
check err.txt "^sweep: 6 runs of disks.lua, 2 at a time"
check err.txt "^sweep: \[[0-9]/6\] E=-5,t_end=0\.1: failed \(status 2\)"
check err.txt "^sweep: 6 runs, 2 failed; summary in .*/runs/summary.md"
for d in "E=1000,t_end=0.1" "E=1000,t_end=0.2" "E=2000,t_end=0.1" "E=2000,t_end=0.2"; do
  for f in run.txt stdout.txt stderr.txt report.json last.png; do
    [ -f "runs/$d/$f" ] || { echo "FAIL: runs/$d/$f missing"; fail=1; }
  done
done
check "runs/E=1000,t_end=0.2/stderr.txt" "^lamina: t = 0\.1 step 100: material\.E = 1500"
check "runs/E=1000,t_end=0.2/stdout.txt" "^report: steps = 200$"
check runs/summary.csv "^run,E,t_end,fail,status,wall_s,energy,steps,vx,error$"
check runs/summary.csv '^"E=1000,t_end=0\.1",1000,0\.1,no,0,[0-9.]+,[0-9.e-]+,100,[0-9.e-]+,$'
check runs/summary.csv '^"E=2000,t_end=0\.2",2000,0\.2,no,0,[0-9.]+,[0-9.e-]+,200,[0-9.e-]+,$'
check runs/summary.csv '^"E=-5,t_end=0\.2",-5,0\.2,no,2,[0-9.]+,,,,.*disks\.lua:[0-9]+: lamina\.elastic: .*E'
[ "$(wc -l < runs/summary.csv)" -eq 7 ] || { echo "FAIL: summary.csv is not 7 lines"; fail=1; }
check runs/summary.md "^# Sweep of disks.lua$"
check runs/summary.md "^6 runs, 2 failed\.$"
check runs/summary.md "^\| run \| E \| t_end \| fail \| status \| wall \(s\) \| energy \| steps \| vx \| error \|$"
check runs/summary.md "^\| E=-5,t_end=0\.1 \| -5 \| 0\.1 \| no \| 2 \| "
check out.txt "^\| E=2000,t_end=0\.2 \| 2000 \| 0\.2 \| no \| 0 \| "
[ $fail -eq 0 ] || show out.txt err.txt runs/summary.csv
exit $fail
