#!/bin/sh
# Ctrl-C during a long run at the prompt stops it at a step boundary and
# returns to the prompt with the simulation intact: the step printed
# afterwards is the one the interrupt message names, and stepping goes on.
# Ctrl-C in a plain Lua loop typed at the prompt stops it too.
. "$(dirname "$0")/lib.sh"
mkfifo in.fifo || exit 1
"$LAMINA" repl "$SRC/disks.lua" < in.fifo > out.txt 2> err.txt &
pid=$!
exec 3> in.fifo
echo 'print("running"); sim:run{t_end = 1e7}' >&3
if wait_for out.txt "^running$"; then
  sleep 1
  kill -INT $pid
fi
echo 'print("after", sim.nstep, sim.nstep == math.floor(sim.t / sim.dt + 0.5))' >&3
echo 'sim:step(3); print("stepped", sim.nstep)' >&3
# Ctrl-C in plain Lua code typed at the prompt (a Lua hook stops it)
echo 'print("looping"); n = 0; while true do n = n + 1 end' >&3
if wait_for out.txt "^looping$"; then
  sleep 1
  kill -INT $pid
fi
echo 'print("looped", n > 0, sim.nstep)' >&3
exec 3>&-
wait_exit $pid 60
[ "$status" -eq 0 ] || { echo "FAIL: exit status $status"; fail=1; }
check err.txt "^stdin:1: interrupted at t = [0-9.e+]+, step [0-9]+$"
step=$(sed -n 's/.*interrupted at t = .*, step \([0-9]*\)$/\1/p' err.txt)
check out.txt "^after	$step	true$"
check out.txt "^stepped	$((step + 3))$"
check err.txt "^stdin:1: interrupted$"
check out.txt "^looped	true	$((step + 3))$"
[ $fail -eq 0 ] || show out.txt err.txt
exit $fail
