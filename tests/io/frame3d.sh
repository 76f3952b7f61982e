#!/bin/sh
# A 3D sim's frame through the Lua API (issue 34 item 4): frame3d.sh LAMINA SRC_TESTS_DIR
# The script's frame is written (a PNG), and the same script twice gives the
# same bytes (determinism per backend; cairo here so the test needs no GL).
set -u
L=$1; T=$2/io; O=out/frame3d
rm -rf "$O"; mkdir -p "$O"
fail() { echo "frame3d: FAILED: $*"; exit 1; }
# the same command twice (the provenance chunks carry the command line)
"$L" run "$T/frame3d.lua" --set out=$O/a > $O/a.out 2>&1 || fail "first run: $(cat $O/a.out)"
[ -s $O/a/ball.png ] || fail "no frame written"
head -c 8 $O/a/ball.png | od -An -tx1 | grep -q "89 50 4e 47 0d 0a 1a 0a" || fail "not a PNG"
mv $O/a/ball.png $O/first.png
"$L" run "$T/frame3d.lua" --set out=$O/a > $O/b.out 2>&1 || fail "second run: $(cat $O/b.out)"
cmp -s $O/first.png $O/a/ball.png || fail "the same script drew different bytes"
echo "frame3d: $(wc -c < $O/first.png) bytes, identical twice"
