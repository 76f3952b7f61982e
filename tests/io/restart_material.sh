#!/bin/sh
# A live material change survives a restart (issue 33 item 1):
# restart_material.sh LAMINA SRC_TESTS_DIR. The uninterrupted run to
# t = 0.1 and a run to 0.06 restarted from its checkpoint at 0.05 must
# print the same E (2000, set by a callback at 0.03 that the restarted run
# skips) and the same state hash.
set -u
L=$1; T=$2/io; O=out/restart_material
rm -rf "$O"; mkdir -p "$O"
fail() { echo "restart_material: FAILED: $*"; exit 1; }
"$L" run "$T/restart_material.lua" --set out=$O/a > $O/a.out 2>&1 || fail "reference: $(cat $O/a.out)"
"$L" run "$T/restart_material.lua" --set out=$O/b --set t_end=0.06 > $O/b1.out 2>&1 \
  || fail "run to 0.06: $(cat $O/b1.out)"
"$L" run "$T/restart_material.lua" --set out=$O/b --restart $O/b.ckpt > $O/b2.out 2>&1 \
  || fail "restart: $(cat $O/b2.out)"
RA=$(grep '^RESULT' $O/a.out); RB=$(grep '^RESULT' $O/b2.out)
case "$RA" in "RESULT E 2000 hash "*) ;; *) fail "reference printed '$RA'" ;; esac
[ "$RB" = "$RA" ] || fail "restarted: '$RB', uninterrupted: '$RA'"
echo "restart_material: $RB after the restart, as uninterrupted"
