#!/bin/sh
# check_broken.sh LAMINA SCRIPTS GALLERY BROKEN
# Copies a good GALLERY to BROKEN and breaks it in each way `lamina gallery
# --check` must catch - a missing thumbnail, a folder without a script, a
# dead link in the index, a missing index.html - then runs the check, which
# must exit 1 naming every problem.
lamina=$1 scripts=$2 gallery=$3 broken=$4
rm -rf "$broken" && cp -r "$gallery" "$broken" || exit 2
rm "$broken/demo/thumb.png"
mkdir "$broken/orphan"
printf '\n[a dead link](nowhere/README.md)\n' >> "$broken/README.md"
rm "$broken/index.html"
err=$("$lamina" gallery --check --scripts "$scripts" --gallery "$broken" 2>&1)
rc=$?
echo "$err"
fail=0
[ $rc -eq 1 ] || { echo "FAIL: exit status $rc, expected 1" >&2; fail=1; }
for want in "demo/thumb.png: missing its thumbnail" \
            "orphan/: no script" \
            "links to nowhere/README.md, which does not exist" \
            "index.html: missing" \
            "links to demo/thumb.png, which does not exist"; do
  case "$err" in
    *"$want"*) ;;
    *) echo "FAIL: the check did not report: $want" >&2; fail=1 ;;
  esac
done
exit $fail
