#!/bin/sh
# Issue 31 item 4: under --restart, sim:every(1e-300, f) hung: the events
# already past at the checkpoint's time were skipped by counting multiples of
# 1e-300 up to t. They are computed now (la_next_multiple). The restarted run
# must end at once, with the same step count as the whole run.
# usage: restart_every_tiny.sh LAMINA SCRIPT
lamina=$1 script=$2
mkdir -p out/security
rm -f out/security/restart_every_tiny.ck
"$lamina" run "$script" > out/security/restart_every_tiny.1 2>&1 || {
  cat out/security/restart_every_tiny.1; echo "FAIL: the first run"; exit 1; }
timeout 20 "$lamina" run "$script" --restart out/security/restart_every_tiny.ck \
  > out/security/restart_every_tiny.2 2>&1
st=$?
cat out/security/restart_every_tiny.2
[ $st -ne 124 ] || { echo "FAIL: the restart hung"; exit 1; }
[ $st -eq 0 ] || { echo "FAIL: the restart exited $st"; exit 1; }
grep -q "steps 10$" out/security/restart_every_tiny.2 || { echo "FAIL: not 10 steps"; exit 1; }
echo "ok"
