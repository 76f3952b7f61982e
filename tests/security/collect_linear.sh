#!/bin/sh
# collect_linear.sh LAMINA CLI_DIR - issue 18: `lamina sweep --collect` was
# quadratic in the values of a report (200 000 values took more than 60 s).
# Two runs reporting 200 000 values each are collected within 30 s (a
# linear pass takes well under a second, also under the sanitizers).
lamina=$1 src=$2
rm -rf out/security/collect_linear
mkdir -p out/security
"$lamina" sweep "$src/disks.lua" --set E=1000,2000 --set t_end=0.01 \
  --out out/security/collect_linear >/dev/null 2>&1 || { echo "FAIL: the sweep did not run"; exit 1; }
for rep in out/security/collect_linear/*/report.json; do
  awk 'BEGIN { printf "{\n  \"values\": [\n";
               for (i = 1; i <= 200000; i++)
                 printf "    {\"name\": \"v%d\", \"value\": %d}%s\n", i, i, i < 200000 ? "," : "";
               printf "  ]\n}\n" }' > "$rep"
done
timeout 30 "$lamina" sweep --collect out/security/collect_linear > out/security/collect_linear.txt 2>&1
status=$?
[ $status -ne 124 ] || { echo "FAIL: --collect took more than 30 s"; exit 1; }
[ $status -eq 0 ] || { echo "FAIL: exit status $status"; head -c 2000 out/security/collect_linear.txt; exit 1; }
csv=out/security/collect_linear/summary.csv
head -1 "$csv" | grep -q ",v1,v2,v3," || { echo "FAIL: no report columns in summary.csv"; exit 1; }
head -1 "$csv" | grep -q ",v200000,error$" || { echo "FAIL: the last column is missing"; exit 1; }
[ "$(wc -l < "$csv")" -eq 3 ] || { echo "FAIL: summary.csv is not 3 lines"; exit 1; }
exit 0
