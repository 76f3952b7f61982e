#!/bin/sh
# lamina sweep --emit-jobs prints one shell command per run and runs
# nothing; each line runs as is (here through sh, from another folder, as
# GNU parallel or a Slurm array task would), and --collect builds the
# summary from the folders afterwards.
. "$(dirname "$0")/lib.sh"
"$LAMINA" sweep "$SRC/disks.lua" --set E=1000,2000 --set "fail=no,it's yes" --out runs \
  --emit-jobs > jobs.txt 2> err.txt
status=$?
[ $status -eq 0 ] || { echo "FAIL: --emit-jobs exit status $status"; fail=1; }
[ "$(wc -l < jobs.txt)" -eq 4 ] || { echo "FAIL: jobs.txt is not 4 lines"; fail=1; }
[ ! -e runs ] || { echo "FAIL: --emit-jobs ran something"; fail=1; }
check jobs.txt "^/.* sweep --job /.*/runs/E=1000,fail=no /.*disks\.lua --set E=1000 --set fail=no$"
check jobs.txt "--set 'fail=it'\\\\''s yes'$"
mkdir elsewhere
line=$(sed -n 1p jobs.txt)
(cd elsewhere && sh -c "$line" > ../job1.out 2> ../job1.err)
status=$?
[ $status -eq 0 ] || { echo "FAIL: the emitted line exited with $status"; fail=1; }
check runs/E=1000,fail=no/run.txt "^status 0$"
check runs/E=1000,fail=no/stdout.txt "^report: steps = 300$"
line=$(sed -n 2p jobs.txt)
(cd elsewhere && sh -c "$line" > ../job2.out 2> ../job2.err)
status=$?
[ $status -eq 2 ] || { echo "FAIL: the run with fail=\"it's yes\" exited with $status, expected 2"; fail=1; }
check runs/E=1000,fail=it_s_yes/run.txt "^set fail=it's yes$"
"$LAMINA" sweep --collect runs > collect.out 2> collect.err
status=$?
[ $status -eq 1 ] || { echo "FAIL: --collect exit status $status, expected 1"; fail=1; }
check collect.err "^sweep: 2 runs, 1 failed or unfinished"
check runs/summary.csv "^E=1000,fail=no,1000,no,0,|^\"E=1000,fail=no\",1000,no,0,"
check runs/summary.csv "^\"E=1000,fail=it_s_yes\",1000,it's yes,2,[0-9.]+,[0-9.e-]+,300,[0-9.e-]+,.*disks\.lua:[0-9]+: deliberate failure \(fail = it's yes\)$"
[ $fail -eq 0 ] || show jobs.txt job1.err job2.err collect.out collect.err runs/summary.csv
exit $fail
