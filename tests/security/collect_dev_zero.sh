#!/bin/sh
# collect_dev_zero.sh LAMINA CLI_DIR - issue 18: a report.json linked to
# /dev/zero was read whole, for ever, by `lamina sweep --collect`. Files
# read whole are regular files of a stated size (read_file.h): the collect
# ends, and lists the run.
lamina=$1 src=$2
rm -rf out/security/collect
mkdir -p out/security
"$lamina" sweep "$src/disks.lua" --set E=1000 --set t_end=0.01 --out out/security/collect \
  >/dev/null 2>&1 || { echo "FAIL: the sweep did not run"; exit 1; }
rep=$(ls -d out/security/collect/*/report.json | head -1)
[ -f "$rep" ] || { echo "FAIL: no report.json"; exit 1; }
rm -f "$rep" && ln -s /dev/zero "$rep"
timeout 60 "$lamina" sweep --collect out/security/collect > out/security/collect.txt 2>&1
status=$?
cat out/security/collect.txt
[ $status -ne 124 ] || { echo "FAIL: --collect hung on a report linked to /dev/zero"; exit 1; }
grep -q "^| run | 1000 | 0.01 | 0 |" out/security/collect.txt || { echo "FAIL: the run is not listed"; exit 1; }
exit 0
