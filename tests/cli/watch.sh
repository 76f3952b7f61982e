#!/bin/sh
# lamina watch: runs the script, runs it again after the file changes (one
# summary line per run with time, steps and the reported values); a long
# run is abandoned when the file changes during it; --steps N stops after N
# steps; an error is summarized with file:line.
. "$(dirname "$0")/lib.sh"
# 1. a re-run after a change
cp "$SRC/disks.lua" w1.lua
"$LAMINA" watch w1.lua --max-runs 2 --interval 0.05 --set out=frames > out1.txt 2> err1.txt &
pid=$!
wait_for out1.txt "watch 1:" && echo "-- touched" >> w1.lua
wait_exit $pid 60
[ "$status" -eq 0 ] || { echo "FAIL: exit status $status"; fail=1; }
check out1.txt "^\[[0-9:]+\] watch 1: ok, t = 0\.3, 300 steps, 1 frame, [0-9.]+ s; energy = [0-9.]+, steps = 300, vx = [0-9.]+$"
check out1.txt "^\[[0-9:]+\] watch 2: ok, t = 0\.3, 300 steps"
check err1.txt "^lamina: t = 0\.1 step 100: material\.E = 1500"
# 2. a long run abandoned by a change; the next run has an error
sed 's/lamina.param("t_end", 0.3)/lamina.param("t_end", 1e7)/' "$SRC/disks.lua" > w2.lua
"$LAMINA" watch w2.lua --max-runs 2 --interval 0.05 --log run.log > out2.txt 2> err2.txt &
pid=$!
if wait_for err2.txt "lamina watch: running"; then
  sleep 1
  { cat "$SRC/disks.lua"; echo 'error("broken on purpose")'; } > w2.lua.new
  mv w2.lua.new w2.lua
fi
wait_exit $pid 60
[ "$status" -eq 2 ] || { echo "FAIL: exit status $status, expected 2 (the last run's)"; fail=1; }
check out2.txt "watch 1: abandoned \(the script changed\), t = [0-9.e+]+, [0-9]+ steps"
check out2.txt "watch 2: failed \(status 2\), .*: w2\.lua:[0-9]+: broken on purpose$"
check err2.txt "^lamina: w2\.lua:[0-9]+: broken on purpose$"
check run.log "watch 2: failed"
check run.log "material\.E = 1500"
# 3. --steps and --once
"$LAMINA" watch w1.lua --once --steps 40 > out3.txt 2> err3.txt
status=$?
[ "$status" -eq 0 ] || { echo "FAIL: --once exit status $status"; fail=1; }
check out3.txt "watch 1: ok \(first 40 steps\), t = 0\.04, 40 steps"
# a scenario of exactly N steps ends normally (its report is printed)
"$LAMINA" watch w1.lua --once --steps 300 --set out=frames > out4.txt 2> err4.txt
check out4.txt "watch 1: ok, t = 0\.3, 300 steps, 1 frame, [0-9.]+ s; energy = "
[ $fail -eq 0 ] || show out1.txt err1.txt out2.txt err2.txt out3.txt err3.txt out4.txt err4.txt
exit $fail
