#!/bin/sh
# The repl driven through a pipe: the script pauses before its first
# sim:run, expressions print their values, statements run, a statement can
# span lines, an error at the prompt is printed and the session and state
# go on, a change typed at the prompt is logged with time and step, and
# lamina.resume() finishes the script.
. "$(dirname "$0")/lib.sh"
"$LAMINA" repl "$SRC/disks.lua" > out.txt 2> err.txt <<'LUA'
sim.nstep
sim:step(10)
sim.nstep, sim.t
x = 1 +
  2
x
rubber.E = 3000
nosuch.field = 1
print("after the error", sim.nstep, rubber.E)
print("bodies", #a, #b, sim.n == #a + #b)
local e = sim:energy(); print("energy", e.total > 0)
return t_end, fail
sim:run{t_end = 0.05}
sim.nstep
lamina.resume()
sim.nstep
LUA
status=$?
[ $status -eq 0 ] || { echo "FAIL: exit status $status"; fail=1; }
check err.txt "paused before the first sim:run at .*disks.lua:[0-9]+ \(t = 0, step 0\)"
check err.txt "locals are globals now: t_end, fail, out, a, b"
check out.txt "^0$"
check out.txt "^10	0\.01$"
check out.txt "^3$"
check err.txt "^lamina: t = 0\.01 step 10: material\.E = 3000 \(at the prompt\)$"
check err.txt "^stdin:1: attempt to index a nil value \(global 'nosuch'\)"
check out.txt "^after the error	10	3000\.0$"
check out.txt "^bodies	[0-9]+	[0-9]+	true$"
check out.txt "^energy	true$"
check out.txt "^0\.3	no$"
check out.txt "^50$"
check out.txt "^report: steps = 300$"
check err.txt "the script ran to its end"
check out.txt "^300$"
[ $fail -eq 0 ] || show out.txt err.txt
exit $fail
