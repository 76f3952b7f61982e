#!/bin/sh
# sweep_term.sh LAMINA SCRIPT - issue 18, item 4: SIGTERM to `lamina sweep`
# left its children running. Now the running runs get SIGTERM too (each
# stops at a step boundary and writes its records), no new run starts,
# and the sweep exits 143 once they have ended.
lamina=$1 script=$2 out=out/security/sweep_term
rm -rf "$out"
mkdir -p out/security
"$lamina" sweep "$script" --set k=1,2,3 --jobs 2 --out "$out" --quiet \
  > "$out.txt" 2> "$out.err" &
pid=$!
i=0
while [ "$(ls "$out"/*/started.png 2>/dev/null | wc -l)" -lt 2 ]; do
  i=$((i + 1)); [ $i -gt 600 ] && { echo "FAIL: the runs did not start"; kill -9 $pid; exit 1; }
  sleep 0.1
done
children=$(ps -o pid= --ppid $pid)
[ -n "$children" ] || { echo "FAIL: no child processes seen"; kill -9 $pid; exit 1; }
sleep 0.3
kill -TERM $pid
wait $pid
got=$?
cat "$out.err"
rc=0
[ "$got" = 143 ] || { echo "FAIL: exit status $got, expected 143"; rc=1; }
for c in $children; do
  if kill -0 "$c" 2>/dev/null; then echo "FAIL: child $c still running"; kill -9 "$c"; rc=1; fi
done
n=$(ls "$out"/*/rec.csv 2>/dev/null | wc -l)
[ "$n" -eq 2 ] || { echo "FAIL: $n runs wrote their records, expected 2"; rc=1; }
[ ! -e "$out/k=3" ] || { echo "FAIL: a run started after the signal"; rc=1; }
grep -q "sweep: stopping (SIGTERM): 2 runs stopped, 1 not started" "$out.err" ||
  { echo "FAIL: no stopping message"; rc=1; }
[ -f "$out/summary.csv" ] || { echo "FAIL: no summary"; rc=1; }
exit $rc
