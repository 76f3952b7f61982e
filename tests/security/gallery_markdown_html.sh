#!/bin/sh
# gallery_markdown_html.sh LAMINA HOSTILE_SCRIPTS - issue 31 item 8: a
# gallery script's title, source, "look" text and reported strings went raw
# into gallery/README.md and the figure's README.md; a Markdown viewer
# renders raw HTML, so "<img src=x onerror=...>" ran. A '<' that could open
# a tag is now written &lt; (gallery_index.c markdown_char); "r <= 0.1"
# stays; gallery --check still passes.
lamina=$1 scripts=$2 out=out/security/gallery_md
rm -rf "$out"
mkdir -p "$out"
"$lamina" gallery --scripts "$scripts" --gallery "$out/g" --quiet > "$out.txt" 2>&1 ||
  { cat "$out.txt"; echo "FAIL: the gallery run failed"; exit 1; }
fail=0
for f in "$out/g/README.md" "$out/g/hostile/README.md" "$out/g/index.html"; do
  [ -f "$f" ] || { echo "FAIL: no $f"; fail=1; continue; }
  if grep -E -q '<(img src=x|script|iframe|svg|b>)' "$f"; then
    echo "FAIL: raw HTML in $f:"; grep -E '<(img src=x|script|iframe|svg|b>)' "$f"; fail=1
  fi
done
page="$out/g/hostile/README.md"
for want in '# Hostile &lt;img src=x onerror=alert(1)> title' \
            '**Source:** &lt;script>alert(2)&lt;/script> & r <= 0.1' \
            '&lt;iframe src=javascript:alert(3)>&lt;/iframe>' '&lt;svg onload=alert(4)>'; do
  grep -F -q -- "$want" "$page" || { echo "FAIL: no '$want' in the page:"; cat "$page"; fail=1; }
done
"$lamina" gallery --check --scripts "$scripts" --gallery "$out/g" > "$out.check" 2>&1 ||
  { cat "$out.check"; echo "FAIL: gallery --check"; fail=1; }
exit $fail
