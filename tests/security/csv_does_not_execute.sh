#!/bin/sh
# Issue 31 item 2: no CSV lamina writes for a script runs as shell or Python.
# csv_hostile.lua checks that hostile column names are refused and writes a
# record and a plot CSV with the worst names still accepted; each CSV is then
# run by sh and python3 (a CSV named conftest.py is run by pytest): neither
# may create pwned_sh / pwned_py or print anything.
# usage: csv_does_not_execute.sh LAMINA SCRIPT
set -u
lamina=$1 script=$2
out=out/security/csv_exec
mkdir -p "$out"
rm -f "$out"/pwned_* pwned_sh pwned_py
"$lamina" run "$script" || { echo "FAIL: the script failed"; exit 1; }
# The record CSV (column names from the safe set) fails in both at once: its
# first word / name is "t,step,..." / t, unknown. The plot CSV's quoted
# header is a tuple of plain strings to Python (it runs, doing nothing) and
# one unknown command to sh: what is checked is that nothing is created
# and nothing printed.
for f in "$out/rec.csv" "$out/p.csv"; do
  test -s "$f" || { echo "FAIL: $f not written"; exit 1; }
  head -1 "$f"
  for run in sh python3; do
    said=$(cd "$out" && $run "../../../$f" 2>/dev/null)
    status=$?
    test -z "$said" || { echo "FAIL: $run $f printed: $said"; exit 1; }
    if [ "$f" = "$out/rec.csv" ] && [ $status -eq 0 ]; then
      echo "FAIL: $run ran $f without error"; exit 1
    fi
  done
done
for p in pwned_sh pwned_py "$out/pwned_sh" "$out/pwned_py"; do
  test -e "$p" && { echo "FAIL: $p was created"; exit 1; }
done
echo "ok: neither sh nor python3 runs the CSVs"
