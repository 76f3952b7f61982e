#!/bin/sh
# figure_view3d.sh LAMINA SCRIPT DIR [RUN ARGS...] - runs figure_view3d.lua
# into DIR and checks the PNGs it wrote: the "lamina:view3d" text chunk
# names the backend that drew the 3D views (OSMesa by default when built,
# else EGL; cairo when asked; EGL for "egl" and "gl" where EGL starts), a
# figure written twice is the same file, two equal figures are the same
# file, OSMesa and cairo draw differently, and a figure without 3D panels
# carries no such chunk.
set -u
lamina=$1 script=$2 dir=$3
shift 3
rm -rf "$dir"
out=$("$lamina" run "$script" --set out="$dir" "$@") || { echo "$out"; exit 1; }
echo "$out"
fail=0
no() { echo "figure_view3d.sh: $*" >&2; fail=1; }
# the chunk's value ("keyword\0value"; the chunk's CRC follows the value)
backend() { LC_ALL=C tr '\0' '=' < "$1" | LC_ALL=C grep -a -o 'lamina:view3d=\(osmesa\|egl\|cairo\)' | head -n 1 | sed 's/.*=//'; }
default=$(echo "$out" | sed -n 's/.*default=\([a-z]*\).*/\1/p')
osmesa=$(echo "$out" | sed -n 's/^osmesa=\([a-z]*\).*/\1/p')
egl=$(echo "$out" | sed -n 's/.* egl=\([a-z]*\).*/\1/p')
[ -n "$default" ] || no "the script did not say what it expects"
for f in default_a default_b default_c cairo flat; do
  [ -f "$dir/$f.png" ] || no "$f.png was not written"
done
[ "$(backend "$dir/default_a.png")" = "$default" ] ||
  no "default_a.png: lamina:view3d is '$(backend "$dir/default_a.png")', not '$default'"
cmp -s "$dir/default_a.png" "$dir/default_b.png" || no "a second write of a figure differs"
cmp -s "$dir/default_a.png" "$dir/default_c.png" || no "two equal figures differ"
[ "$(backend "$dir/cairo.png")" = cairo ] || no "backend = 'cairo' is not named cairo"
if [ "$osmesa" = yes ]; then
  [ "$(backend "$dir/osmesa.png")" = osmesa ] || no "backend = 'osmesa' is not named osmesa"
  cmp -s "$dir/osmesa.png" "$dir/cairo.png" && no "OSMesa and cairo drew the same file"
fi
if [ "$egl" = yes ]; then
  [ "$(backend "$dir/egl.png")" = egl ] || no "backend = 'egl' is not named egl"
  [ "$(backend "$dir/gl.png")" = egl ] || no "backend = 'gl' is not EGL where EGL starts"
  cmp -s "$dir/egl.png" "$dir/cairo.png" && no "EGL and cairo drew the same file"
fi
LC_ALL=C grep -q -a 'lamina:view3d' "$dir/flat.png" && no "a figure without 3D panels names a backend"
[ $fail = 0 ] && echo "figure_view3d.sh: ok ($default by default)"
exit $fail
