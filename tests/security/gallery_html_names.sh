#!/bin/sh
# Issue 31 item 2: a script's file name went raw into href and src of
# gallery/index.html (and README.md's links): a name such as
# x"><img src=x onerror=...> injected HTML. Every name reaching HTML is now escaped,
# and links are percent-encoded (gallery_index.c g_url).
# usage: gallery_html_names.sh LAMINA GALLERY_OK_SCRIPTS
lamina=$1 ok=$2 out=out/security/gallery_html
rm -rf "$out"
mkdir -p "$out/scripts"
name='x"><img src=x onerror=alert(1)> & y'
cp "$ok/quick.lua" "$out/scripts/$name.lua" || { echo "FAIL: cannot make the script"; exit 1; }
"$lamina" gallery --scripts "$out/scripts" --gallery "$out/g" --quiet > "$out.txt" 2>&1 ||
  { cat "$out.txt"; echo "FAIL: the gallery run failed"; exit 1; }
fail=0
for f in index.html README.md; do
  [ -f "$out/g/$f" ] || { echo "FAIL: no $f"; fail=1; continue; }
  if grep -F -q '<img src=x' "$out/g/$f"; then
    echo "FAIL: $f holds the raw <img> of the name:"; grep -F '<img src=x' "$out/g/$f"; fail=1
  fi
done
grep -F -q 'href="x%22%3E%3Cimg%20src%3Dx%20onerror%3Dalert%281%29%3E%20%26%20y/README.md"' "$out/g/index.html" ||
  { echo "FAIL: index.html has no percent-encoded link:"; grep -F href "$out/g/index.html"; fail=1; }
grep -F -q '&lt;img src=x onerror=alert(1)&gt;' "$out/g/index.html" ||
  { echo "FAIL: index.html does not show the name escaped"; fail=1; }
"$lamina" gallery --check --scripts "$out/scripts" --gallery "$out/g" > "$out.check" 2>&1 ||
  { cat "$out.check"; echo "FAIL: gallery --check of the escaped index"; fail=1; }
[ $fail -eq 0 ] && echo "ok: the name is escaped in index.html and README.md"
exit $fail
