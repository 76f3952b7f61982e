#!/bin/sh
# collect_unreadable.sh LAMINA CLI_DIR - issue 18, wrong answers: `lamina
# sweep --collect` skipped a run whose record it could not read and said
# "0 failed". Such a run is named and counted; the exit status is 1. A
# record or log linked to /dev/zero is not read for ever.
lamina=$1 src=$2 out=out/security/collect_unreadable
rm -rf "$out"
mkdir -p out/security
"$lamina" sweep "$src/disks.lua" --set E=1000,2000 --set t_end=0.01 --out "$out" \
  >/dev/null 2>&1 || { echo "FAIL: the sweep did not run"; exit 1; }
rm "$out/E=1000/run.txt" && ln -s /dev/zero "$out/E=1000/run.txt"
rm "$out/E=2000/stderr.txt" && ln -s /dev/zero "$out/E=2000/stderr.txt"
timeout 60 "$lamina" sweep --collect "$out" > "$out.txt" 2> "$out.err"
status=$?
cat "$out.err"
rc=0
[ $status -ne 124 ] || { echo "FAIL: --collect hung"; exit 1; }
[ $status -eq 1 ] || { echo "FAIL: exit status $status, expected 1"; rc=1; }
grep -q "cannot read '.*E=1000/run.txt': not a regular file" "$out.err" ||
  { echo "FAIL: the unreadable run is not named"; rc=1; }
grep -q "sweep: 2 runs, 1 failed or unfinished (some unreadable)" "$out.err" ||
  { echo "FAIL: the count is wrong"; rc=1; }
exit $rc
