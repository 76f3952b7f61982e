#!/bin/sh
# A script that calls lamina.pause() runs whole up to that call (its first
# sim:run does not pause it), its locals become globals, and
# lamina.resume() runs the rest.
. "$(dirname "$0")/lib.sh"
"$LAMINA" repl "$SRC/paused.lua" > out.txt 2> err.txt <<'LUA'
sim.nstep
note
rubber.E = 2000
lamina.resume()
sim.nstep
lamina.resume()
print("still here")
LUA
status=$?
[ $status -eq 0 ] || { echo "FAIL: exit status $status"; fail=1; }
check err.txt "paused by lamina.pause\(\) at .*paused.lua:[0-9]+ \(t = 0\.05, step 50\)"
check out.txt "^50$"
check out.txt "^after the first run$"
check err.txt "^lamina: t = 0\.05 step 50: material\.E = 2000 \(at the prompt\)$"
check out.txt "^resumed	100	2000\.0$"
check out.txt "^100$"
check err.txt "lamina.resume: no paused script"
check out.txt "^still here$"
[ $fail -eq 0 ] || show out.txt err.txt
exit $fail
