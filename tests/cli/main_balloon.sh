#!/bin/sh
# The README's first command runs scripts/examples/balloon.lua (.ci/main):
# here to t = 0.3 (past the landing), it must run, write its frames with
# the membrane layers (the lamina:layers chunk names phi and normals) and
# report its gas. Usage: main_balloon.sh LAMINA SCRIPT
set -eu
lamina=$1; script=$2
out=out/main_balloon
rm -rf "$out"
mkdir -p out
"$lamina" run "$script" --set out="$out" --set t_end=0.3 > "$out.log"
cat "$out.log"
n=$(ls "$out"/frame_*.png | wc -l)
[ "$n" -eq 16 ] || { echo "expected 16 frames, found $n"; exit 1; }
grep -q "gas points outside the membrane:" "$out.log"
grep -a -q "membranes=1 with_phi=1 phi=1 normals=1" "$out/frame_000000.png" \
  || { echo "frame_000000.png does not record its membrane's phi and normals layers"; exit 1; }
echo "main_balloon: $n frames"
