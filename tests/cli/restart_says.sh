#!/bin/sh
# lamina run --restart FILE says what it resumed: the file, t and step
# (issue 35 item 5); --quiet keeps it quiet; the resumed run ends where an
# uninterrupted one does (the same state hash).
. "$(dirname "$0")/lib.sh"
"$LAMINA" run "$SRC/frames.lua" --set out=a > a.txt 2>&1 || { show a.txt; exit 1; }
"$LAMINA" run "$SRC/frames.lua" --set out=b --restart a/run.ckpt > b.txt 2>&1 || { show b.txt; exit 1; }
check b.txt "^lamina: resumed a/run\.ckpt at t = 0\.1, step 100$"
ha=$(sed -n 's/^RESULT .* hash //p' a.txt)
hb=$(sed -n 's/^RESULT .* hash //p' b.txt)
[ -n "$ha" ] && [ "$ha" = "$hb" ] || { echo "FAIL: hash $hb after the restart, $ha without"; fail=1; }
check_not a.txt "resumed"
"$LAMINA" run "$SRC/frames.lua" --set out=c --restart a/run.ckpt --quiet > c.txt 2>&1 || { show c.txt; exit 1; }
check_not c.txt "resumed"
[ $fail -eq 0 ] || show a.txt b.txt
exit $fail
