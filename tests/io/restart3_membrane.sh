#!/bin/sh
# --restart of a 3D script with membranes is refused (issue 34 item 2): the
# 3D state file holds no membrane points, so the restarted run would put
# the script's fresh membranes beside restored particles.
# restart3_membrane.sh LAMINA SRC_TESTS_DIR
set -u
L=$1; T=$2/io; O=out/restart3_membrane
rm -rf "$O"; mkdir -p "$O"
fail() { echo "restart3_membrane: FAILED: $*"; exit 1; }
"$L" run "$T/restart3_membrane.lua" --set out=$O/a > $O/a.out 2>&1 || fail "checkpoint run: $(cat $O/a.out)"
[ -s $O/a.ckpt ] || fail "no checkpoint written"
"$L" run "$T/restart3_membrane.lua" --set out=$O/b --set membrane=true --restart $O/a.ckpt > $O/b.out 2>&1
st=$?
[ $st -eq 2 ] || fail "exit status $st, expected 2: $(cat $O/b.out)"
pat="the script's 3D simulation has membranes, which a 3D checkpoint does not hold"
grep -q -- "$pat" $O/b.out || fail "no '$pat' in: $(cat $O/b.out)"
echo "restart3_membrane: refused: $(grep -- "$pat" $O/b.out | head -1)"
