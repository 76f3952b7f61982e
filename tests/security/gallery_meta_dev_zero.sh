#!/bin/sh
# gallery_meta_dev_zero.sh LAMINA SCRIPTS - issue 18: a figure's meta.json
# (or report.json) linked to /dev/zero was read whole, for ever. Files read
# whole are regular files of a stated size (read_file.h): the gallery
# treats the figure as stale and renders it again.
lamina=$1 scripts=$2 out=out/security/gallery_meta
rm -rf "$out"
mkdir -p out/security
"$lamina" gallery --scripts "$scripts" --gallery "$out" --quiet >/dev/null 2>&1 ||
  { echo "FAIL: the first gallery run failed"; exit 1; }
[ -f "$out/quick/meta.json" ] || { echo "FAIL: no meta.json"; ls -R "$out"; exit 1; }
rm "$out/quick/meta.json" && ln -s /dev/zero "$out/quick/meta.json"
timeout 60 "$lamina" gallery --scripts "$scripts" --gallery "$out" > "$out.txt" 2>&1
status=$?
cat "$out.txt"
[ $status -ne 124 ] || { echo "FAIL: the gallery hung on a meta.json linked to /dev/zero"; exit 1; }
[ $status -eq 0 ] || { echo "FAIL: exit status $status"; exit 1; }
[ -f "$out/quick/meta.json" ] && [ ! -L "$out/quick/meta.json" ] ||
  { echo "FAIL: meta.json was not written again"; exit 1; }
exit 0
