#!/bin/sh
# Progress lines: off a terminal, a plain line at each tenth of a run that
# lasts longer than the threshold (LAMINA_PROGRESS_AFTER, 0 here), each a
# line of its own; --quiet silences them.
. "$(dirname "$0")/lib.sh"
LAMINA_PROGRESS_AFTER=0 "$LAMINA" run "$SRC/disks.lua" --set t_end=1 --set out=o > out.txt 2> err.txt
status=$?
[ $status -eq 0 ] || { echo "FAIL: exit status $status"; fail=1; }
check err.txt "^lamina: progress 10 %: step 100 of 1000, t = 0\.1 of 1, [0-9]+ steps/s, ETA [0-9.]+ s$"
check err.txt "^lamina: progress 90 %: step 900 of 1000"
n=$(grep -c "^lamina: progress" err.txt)
[ "$n" -eq 9 ] || { echo "FAIL: $n progress lines, expected 9"; fail=1; }
LAMINA_PROGRESS_AFTER=0 "$LAMINA" run "$SRC/disks.lua" --set t_end=1 --set out=o --quiet > out2.txt 2> err2.txt
check_not err2.txt "progress"
[ $fail -eq 0 ] || show err.txt err2.txt
exit $fail
