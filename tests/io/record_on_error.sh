#!/bin/sh
# record_on_error.sh LAMINA TESTS: the callback error exits 2 with its
# message, and the recorder's CSV holds the rows up to it (t = 0 .. 0.05).
L=$1; T=$2/io
mkdir -p out; rm -f out/record_on_error.csv
"$L" run "$T/record_on_error.lua" > out/record_on_error.out 2>&1; rc=$?
[ $rc -eq 2 ] || { echo "FAILED: exit $rc, expected 2"; cat out/record_on_error.out; exit 1; }
grep -q "a callback failed" out/record_on_error.out || { echo "FAILED: no message"; exit 1; }
[ -f out/record_on_error.csv ] || { echo "FAILED: the CSV was lost"; exit 1; }
rows=$(($(wc -l < out/record_on_error.csv) - 1))
[ $rows -eq 6 ] || { echo "FAILED: $rows rows, expected 6 (t = 0 .. 0.05)"; cat out/record_on_error.csv; exit 1; }
echo "record_on_error: exit 2, CSV kept with its $rows rows"
