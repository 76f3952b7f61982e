#!/bin/sh
# A 3D frame with membranes (issue 34 items 2, 4): frame3d_membrane.sh LAMINA SRC_TESTS_DIR
# The lamina:layers chunk counts the membrane points drawn (#a + #b, the
# handles' counts printed by the script), those drawn with normals and the
# membranes drawn with their phi = 1 surface (on by default); a frame
# without them has no membrane field (so frames without membranes keep
# their bytes), and the normals' arrows and the phi surfaces change the
# pixels, the trilinear construction's differently from the membranes' own.
set -u
L=$1; S=$2; O=out/frame3d_membrane
rm -rf "$O"; mkdir -p "$O"
fail() { echo "frame3d_membrane: FAILED: $*"; exit 1; }
"$L" run "$S/io/frame3d_membrane.lua" --set out=$O > $O/run.out 2>&1 || fail "run: $(cat $O/run.out)"
set -- $(grep '^points ' $O/run.out)
n=$(($2 + $3))
[ "$n" -gt 0 ] || fail "no points printed"
layers() { python3 -c "import sys; sys.path.insert(0, '$S'); from png_text import png_texts; print(png_texts(sys.argv[1])['lamina:layers'])" "$1"; }
l1=$(layers $O/normals.png); l2=$(layers $O/points.png); l3=$(layers $O/none.png)
l4=$(layers $O/nophi.png); l5=$(layers $O/linear.png)
[ "$l1" = "dim=3 particles=0 slices=0 isosurfaces=0 membrane_points=$n normals=$n membranes=2 phi=2" ] || fail "normals.png: $l1 (want $n points and normals, 2 phi)"
[ "$l2" = "dim=3 particles=0 slices=0 isosurfaces=0 membrane_points=$n normals=0 membranes=2 phi=2" ] || fail "points.png: $l2"
[ "$l3" = "dim=3 particles=0 slices=0 isosurfaces=0" ] || fail "none.png: $l3"
[ "$l4" = "dim=3 particles=0 slices=0 isosurfaces=0 membrane_points=$n normals=0 membranes=2 phi=0" ] || fail "nophi.png: $l4"
[ "$l5" = "$l1" ] || fail "linear.png: $l5"
# the pixels (the IDAT chunks, not the text) differ: the arrows are drawn
idat() { python3 -c "
import struct, sys, zlib
d = open(sys.argv[1], 'rb').read()[8:]
px = b''
while d:
    n, t = struct.unpack('>I4s', d[:8])
    if t == b'IDAT': px += d[8:8 + n]
    d = d[12 + n:]
print(zlib.crc32(zlib.decompress(px)))
" "$1"; }
[ "$(idat $O/normals.png)" != "$(idat $O/points.png)" ] || fail "the normals drew nothing"
[ "$(idat $O/points.png)" != "$(idat $O/none.png)" ] || fail "the membranes drew nothing"
[ "$(idat $O/points.png)" != "$(idat $O/nophi.png)" ] || fail "phi drew nothing"
[ "$(idat $O/linear.png)" != "$(idat $O/normals.png)" ] || fail "the trilinear construction drew the same"
echo "frame3d_membrane: $n membrane points drawn, with and without normals and phi; layers '$l1'"
