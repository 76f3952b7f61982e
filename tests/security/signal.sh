#!/bin/sh
# signal.sh LAMINA SCRIPT OUT SIGNAL STATUS - issue 18, item 5: SIGINT or
# SIGTERM during `lamina run` stops it at a step boundary, writes the
# sim:record CSV (it was lost), leaves no temporary file and exits with
# 128 + the signal's number.
lamina=$1 script=$2 out=$3 sig=$4 want=$5
rm -rf "$out"
"$lamina" run "$script" --set out="$out" --quiet 2>"$out.err" &
pid=$!
i=0
while [ ! -f "$out/started.png" ]; do   # the run has begun
  i=$((i + 1)); [ $i -gt 600 ] && { echo "FAIL: the run did not start"; kill -9 $pid; exit 1; }
  sleep 0.1
done
sleep 0.5
kill -"$sig" $pid
wait $pid
got=$?
cat "$out.err"
rc=0
[ "$got" = "$want" ] || { echo "FAIL: exit status $got, expected $want"; rc=1; }
grep -q "interrupted.* at t = " "$out.err" || { echo "FAIL: no 'interrupted at t = ' message"; rc=1; }
rows=$(wc -l < "$out/rec.csv" 2>/dev/null || echo 0)
[ "$rows" -ge 2 ] || { echo "FAIL: rec.csv has $rows lines (the records were lost)"; rc=1; }
head -1 "$out/rec.csv" | grep -q "^t,step,kinetic" || { echo "FAIL: rec.csv has no header"; rc=1; }
ls "$out" | grep -q "\.tmp\." && { echo "FAIL: temporary files left: $(ls "$out")"; rc=1; }
exit $rc
