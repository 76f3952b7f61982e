#!/bin/sh
# Checkpoint and restart (issue 20 item 2): restart.sh LAMINA SRC_TESTS_DIR
#  1. an uninterrupted run to t = 0.2 gives the reference hash and CSV;
#  2. a run to t = 0.1 (checkpoints at 0.05 and 0.1) restarted to t = 0.2
#     gives the same hash, bit for bit, and the same CSV;
#  3. a slowed run killed with SIGKILL as soon as its first checkpoint
#     exists, restarted, gives the same hash;
#  4. refused with exit 2 and a message: a truncated checkpoint, another
#     format version, one from another script.
set -u
L=$1; T=$2/io; O=out/restart
rm -rf "$O"; mkdir -p "$O"
fail() { echo "restart: FAILED: $*"; exit 1; }
hash_of() { sed -n 's/^RESULT .* hash \([0-9a-f]*\)$/\1/p' "$1"; }

"$L" run "$T/restart.lua" --set out=$O/a > $O/a.out 2>&1 || fail "reference run: $(cat $O/a.out)"
HA=$(hash_of $O/a.out); [ -n "$HA" ] || fail "no hash in the reference run"

"$L" run "$T/restart.lua" --set out=$O/b --set t_end=0.1 > $O/b1.out 2>&1 || fail "run to 0.1"
cp $O/b.ckpt $O/b_at_0.1.ckpt
"$L" run "$T/restart.lua" --set out=$O/b --restart $O/b_at_0.1.ckpt > $O/b2.out 2>&1 \
  || fail "restart: $(cat $O/b2.out)"
HB=$(hash_of $O/b2.out)
[ "$HB" = "$HA" ] || fail "restarted at t = 0.1: hash $HB, uninterrupted $HA"
cmp -s $O/a.csv $O/b.csv || fail "the restarted run's CSV differs from the uninterrupted one's"
echo "restart: resumed at t = 0.1 -> hash $HB = $HA, CSV identical"

"$L" run "$T/restart.lua" --set out=$O/k --set slow=0.01 > $O/k1.out 2>&1 &
PID=$!
i=0
while [ ! -f $O/k.ckpt ] && [ $i -lt 600 ]; do sleep 0.05; i=$((i + 1)); done
kill -9 $PID 2>/dev/null; wait $PID 2>/dev/null
[ -f $O/k.ckpt ] || fail "the slowed run wrote no checkpoint"
grep -q RESULT $O/k1.out && fail "the slowed run finished before it was killed"
TK=$(sed -n 's/^t \(.*\)$/\1/p' $O/k.ckpt | head -1)
"$L" run "$T/restart.lua" --set out=$O/k --restart $O/k.ckpt > $O/k2.out 2>&1 \
  || fail "restart after SIGKILL: $(cat $O/k2.out)"
HK=$(hash_of $O/k2.out)
[ "$HK" = "$HA" ] || fail "killed and resumed at t = $TK: hash $HK, uninterrupted $HA"
echo "restart: killed (SIGKILL) after its checkpoint at t = $TK, resumed -> hash $HK = $HA"

expect2() {   # expect2 NAME PATTERN CHECKPOINT [script]
  s=${4:-$T/restart.lua}
  "$L" run "$s" --set out=$O/x --restart "$3" > $O/x.out 2>&1; rc=$?
  [ $rc -eq 2 ] || fail "$1: exit $rc, expected 2"
  grep -q "$2" $O/x.out || fail "$1: no '$2' in: $(cat $O/x.out)"
  echo "restart: $1 refused: $(grep -o "$2.*" $O/x.out | head -1)"
}
head -c 5000 $O/b_at_0.1.ckpt > $O/trunc.ckpt
expect2 truncated "does not fit\|truncated" $O/trunc.ckpt
sed '1s/LAMINA-CHECKPOINT [0-9]*/LAMINA-CHECKPOINT 9/' $O/b_at_0.1.ckpt > $O/v9.ckpt
expect2 "another version" "is checkpoint format 9" $O/v9.ckpt
expect2 "another script" "does not fit" $O/b_at_0.1.ckpt "$T/vtk_export.lua"
echo "restart: all checks passed"
