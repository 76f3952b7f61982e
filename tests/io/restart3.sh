#!/bin/sh
# Checkpoint and restart of a 3D run (issue 34 item 1): restart3.sh LAMINA SRC_TESTS_DIR
#  1. an uninterrupted run to t = 0.2 gives the reference hash and CSV;
#  2. a run to t = 0.1 (checkpoints at 0.05 and 0.1) restarted to t = 0.2
#     gives the same hash, bit for bit, and the same CSV;
#  3. refused with exit 2 and a message: a 2D run's checkpoint given to the
#     3D script (and the 3D one to a 2D script), a truncated checkpoint, one
#     from a script that builds other bodies.
set -u
L=$1; T=$2/io; O=out/restart3
rm -rf "$O"; mkdir -p "$O"
fail() { echo "restart3: FAILED: $*"; exit 1; }
hash_of() { sed -n 's/^RESULT .* hash \([0-9a-f]*\)$/\1/p' "$1"; }

"$L" run "$T/restart3.lua" --set out=$O/a > $O/a.out 2>&1 || fail "reference run: $(cat $O/a.out)"
HA=$(hash_of $O/a.out); [ -n "$HA" ] || fail "no hash in the reference run"

"$L" run "$T/restart3.lua" --set out=$O/b --set t_end=0.1 > $O/b1.out 2>&1 || fail "run to 0.1"
cp $O/b.ckpt $O/b_at_0.1.ckpt
"$L" run "$T/restart3.lua" --set out=$O/b --restart $O/b_at_0.1.ckpt > $O/b2.out 2>&1 \
  || fail "restart: $(cat $O/b2.out)"
grep -q "resumed .* at t = 0.1, step 100" $O/b2.out || fail "no 'resumed' line: $(cat $O/b2.out)"
HB=$(hash_of $O/b2.out)
[ "$HB" = "$HA" ] || fail "restarted at t = 0.1: hash $HB, uninterrupted $HA"
cmp -s $O/a.csv $O/b.csv || fail "the restarted run's CSV differs from the uninterrupted one's"
echo "restart3: resumed at t = 0.1 -> hash $HB = $HA, CSV identical"

refused() {   # refused WHAT PATTERN ARGS...: exit status 2 and the message
  what=$1; pat=$2; shift 2
  "$L" run "$@" > $O/r.out 2>&1; st=$?
  [ $st -eq 2 ] || fail "$what: exit status $st, expected 2: $(cat $O/r.out)"
  grep -q -- "$pat" $O/r.out || fail "$what: no '$pat' in: $(cat $O/r.out)"
  echo "restart3: $what refused: $(grep -- "$pat" $O/r.out | head -1)"
}
"$L" run "$T/restart3.lua" --set out=$O/two --set make2d=true > $O/two.out 2>&1 \
  || fail "the 2D checkpoint: $(cat $O/two.out)"
refused "a 2D checkpoint" "is a checkpoint of a 2D simulation; the script's is 3D" \
  "$T/restart3.lua" --set out=$O/c --restart $O/two.ckpt
refused "a 3D checkpoint to a 2D script" "is a checkpoint of a 3D simulation; the script's is 2D" \
  "$T/restart3.lua" --set out=$O/c --set make2d=true --restart $O/b_at_0.1.ckpt
head -c $(($(wc -c < $O/b_at_0.1.ckpt) - 100)) $O/b_at_0.1.ckpt > $O/short.ckpt
refused "a truncated checkpoint" "is truncated" \
  "$T/restart3.lua" --set out=$O/c --restart $O/short.ckpt
refused "another script's checkpoint" "does not fit the script: it holds" \
  "$T/restart3.lua" --set out=$O/c --set radius=0.12 --restart $O/b_at_0.1.ckpt
echo "restart3: passed"
