#!/bin/sh
# Issue 31 item 6: `lamina run s.lua > /dev/full` returned 0 (what the script
# printed was lost), and `lamina run s.lua | head` was killed by SIGPIPE
# before its records were written. A write error on stdout now fails the run
# (status 2, saying so); SIGPIPE stops it as SIGTERM does (status 141, the
# record CSV written).
# usage: stdout_errors.sh LAMINA
lamina=$1
dir=out/security/stdout_errors
rm -rf "$dir"; mkdir -p "$dir"
fail=0
echo 'print("a line")' > "$dir/one.lua"
if [ -w /dev/full ]; then
  "$lamina" run "$dir/one.lua" > /dev/full 2> "$dir/full.err"
  st=$?
  [ $st -eq 2 ] || { echo "FAIL: > /dev/full: status $st"; fail=1; }
  grep -q "cannot write the script's output to stdout: No space left on device" "$dir/full.err" ||
    { echo "FAIL: > /dev/full: no message"; cat "$dir/full.err"; fail=1; }
else
  echo "note: no /dev/full here; that case skipped"
fi
cat > "$dir/chatty.lua" <<'LUA'
local sim = lamina.sim{ dt = 1e-3, domain = {0, 0, 1, 1}, cell = 0.1 }
sim:record{ file = "out/security/stdout_errors/rec.csv", every = 1e-3, energy = true }
sim:every(1e-3, function(s) for i = 1, 100 do print(s.t, i) end end)
sim:run{ t_end = 1e4 }
LUA
( "$lamina" run "$dir/chatty.lua" 2> "$dir/pipe.err"; echo $? > "$dir/pipe.status" ) | head -3 > /dev/null
st=$(cat "$dir/pipe.status")
[ "$st" = 141 ] || { echo "FAIL: | head: status $st, expected 141"; cat "$dir/pipe.err"; fail=1; }
grep -q "interrupted (SIGPIPE) at t = " "$dir/pipe.err" || { echo "FAIL: | head: no message"; fail=1; }
[ "$(wc -l < "$dir/rec.csv" 2>/dev/null || echo 0)" -ge 2 ] || { echo "FAIL: | head: rec.csv lost"; fail=1; }
[ $fail -eq 0 ] && echo "ok: /dev/full fails the run, SIGPIPE keeps the records"
exit $fail
