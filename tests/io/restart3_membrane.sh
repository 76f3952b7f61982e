#!/bin/sh
# Checkpoint and restart of a 3D run with membranes (issue 34 item 2):
# restart3_membrane.sh LAMINA SRC_TESTS_DIR
#  1. an uninterrupted run to t = 0.06 gives the reference hash and CSV;
#  2. a run to t = 0.03 restarted from its checkpoint to t = 0.06 gives the
#     same hash, bit for bit, and the same CSV (the membranes' tensions, a
#     sheet's lowest point and the pin's reaction among its columns);
#  3. refused with exit 2 and a message: the checkpoint of a script without
#     membranes, one of a sheet sampled at another spacing, and checkpoints
#     whose membrane part is damaged (a point moved out of the domain, a
#     NaN tension) - the file is untrusted input (docs/security.md).
set -u
L=$1; T=$2/io; O=out/restart3_membrane
rm -rf "$O"; mkdir -p "$O"
fail() { echo "restart3_membrane: FAILED: $*"; exit 1; }
hash_of() { sed -n 's/^RESULT .* hash \([0-9a-f]*\)$/\1/p' "$1"; }
S=$T/restart3_membrane.lua

"$L" run "$S" --set out=$O/a > $O/a.out 2>&1 || fail "reference run: $(cat $O/a.out)"
HA=$(hash_of $O/a.out); [ -n "$HA" ] || fail "no hash in the reference run"

"$L" run "$S" --set out=$O/b --set t_end=0.03 > $O/b1.out 2>&1 || fail "run to 0.03: $(cat $O/b1.out)"
cp $O/b.ckpt $O/b_at_0.03.ckpt
"$L" run "$S" --set out=$O/b --restart $O/b_at_0.03.ckpt > $O/b2.out 2>&1 \
  || fail "restart: $(cat $O/b2.out)"
grep -q "resumed .* at t = 0.03, step 30" $O/b2.out || fail "no 'resumed' line: $(cat $O/b2.out)"
HB=$(hash_of $O/b2.out)
[ "$HB" = "$HA" ] || fail "restarted at t = 0.03: hash $HB, uninterrupted $HA"
cmp -s $O/a.csv $O/b.csv || fail "the restarted run's CSV differs from the uninterrupted one's"
head -1 $O/a.csv | grep -q "sheet_T" || fail "no membrane column in the CSV"
echo "restart3_membrane: resumed at t = 0.03 -> hash $HB = $HA, CSV identical ($(wc -l < $O/a.csv) lines)"

refused() {   # refused WHAT PATTERN ARGS...: exit status 2 and the message
  what=$1; pat=$2; shift 2
  "$L" run "$@" > $O/r.out 2>&1; st=$?
  [ $st -eq 2 ] || fail "$what: exit status $st, expected 2: $(cat $O/r.out)"
  grep -q -- "$pat" $O/r.out || fail "$what: no '$pat' in: $(cat $O/r.out)"
  echo "restart3_membrane: $what refused: $(grep -- "$pat" $O/r.out | head -1)"
}
"$L" run "$S" --set out=$O/none --set membrane=false --set t_end=0.01 > $O/none.out 2>&1 \
  || fail "the run without membranes: $(cat $O/none.out)"
refused "a checkpoint without membranes" "does not fit the script: it holds 0 membrane points" \
  "$S" --set out=$O/c --restart $O/none.ckpt
refused "another sheet's checkpoint" "does not fit the script: it holds [0-9]* membrane points" \
  "$S" --set out=$O/c --set spacing=0.04 --restart $O/b_at_0.03.ckpt
# the membrane part's first x (point 1) and its first stress (array 21)
/usr/bin/python3 - "$O/b_at_0.03.ckpt" "$O" <<'PY' || fail "could not mutate the checkpoint"
import struct, sys
data = open(sys.argv[1], "rb").read()
off = data.index(b"\n\n") + 2                      # the engine part after the text header
assert data[off:off + 8] == b"LM3STATE"
nmat, = struct.unpack_from("<I", data, off + 12)
n, = struct.unpack_from("<Q", data, off + 16)
np_, = struct.unpack_from("<Q", data, off + 32)
nmem, npins = struct.unpack_from("<II", data, off + 40)
mem = off + 48 + (6 + 12 * nmat) * 8 + 8 + n * (15 * 8 + 1) + nmem * 16 + npins * 32
def put(name, array, value):
    b = bytearray(data)
    struct.pack_into("<d", b, mem + array * np_ * 8, value)
    open(sys.argv[2] + "/" + name, "wb").write(b)
put("far.ckpt", 0, 7.5)                            # x of point 1 beyond the domain
put("nan.ckpt", 20, float("nan"))                  # s11 of point 1
PY
refused "a membrane point outside the domain" "is damaged: membrane point 1 has x = 7.5 outside the domain" \
  "$S" --set out=$O/c --restart $O/far.ckpt
refused "a NaN membrane stress" "is damaged: membrane point 1 has a value that is not finite (array 21)" \
  "$S" --set out=$O/c --restart $O/nan.ckpt
echo "restart3_membrane: passed"
