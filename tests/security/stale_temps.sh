#!/bin/sh
# stale_temps.sh LAMINA SCRIPT - issue 18, item 5: `kill -9` during a write
# left "*.png.tmp.*" files that nothing removed. A temporary is named
# "<target>.tmp.<host>.<pid>.XXXXXX"; the next write into the folder removes
# those whose process is gone, and keeps those of live processes.
lamina=$1 script=$2 dir=out/security/stale
rm -rf "$dir"
mkdir -p "$dir"
host=$(hostname 2>/dev/null || uname -n)
dead=$(sh -c 'echo $$')                 # a process that has ended
sleep 30 & live=$!                      # one that is alive
echo x > "$dir/old.png.tmp.$host.$dead.aB3dE9"
echo x > "$dir/old.png.tmp.$host.$live.aB3dE9"
echo x > "$dir/old.png.tmp.otherhost.$dead.aB3dE9"
echo x > "$dir/unrelated.tmp.txt"
"$lamina" run "$script" --set out="$dir" --quiet 2>/dev/null
rc=0
[ ! -e "$dir/old.png.tmp.$host.$dead.aB3dE9" ] || { echo "FAIL: the stale temporary is still there"; rc=1; }
[ -e "$dir/old.png.tmp.$host.$live.aB3dE9" ] || { echo "FAIL: a live process's temporary was removed"; rc=1; }
[ -e "$dir/old.png.tmp.otherhost.$dead.aB3dE9" ] || { echo "FAIL: another host's temporary was removed"; rc=1; }
[ -e "$dir/unrelated.tmp.txt" ] || { echo "FAIL: an unrelated file was removed"; rc=1; }
[ -f "$dir/frame.png" ] || { echo "FAIL: the frame was not written"; rc=1; }
kill $live 2>/dev/null
exit $rc
