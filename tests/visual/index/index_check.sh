#!/bin/sh
# index_check.sh LAMINA CHROMIUM GALLERY BASELINE WORK - the gallery's
# index.html as a reader sees it (issue 32 item 9), in Debian's headless
# Chromium:
#   1. it fits 1400 px without scrolling sideways: width.html loads it in a
#      1400 px frame and writes the document's scrollWidth into its title;
#   2. its screenshot at 1400 x 1000 is the baseline's (lamina diff); a
#      missing baseline is written as the candidate and the test fails.
# Exit 0 when both hold.
lamina=$1 chromium=$2 gallery=$3 baseline=$4 work=$5
here=$(cd "$(dirname "$0")" && pwd)
index=$(cd "$gallery" && pwd)/index.html
mkdir -p "$work"
run_chromium() {   # quiet: Chromium's own complaints (D-Bus, GPU) go to a log
  timeout 120 "$chromium" --headless --no-sandbox --disable-gpu --hide-scrollbars \
    --allow-file-access-from-files --virtual-time-budget=5000 "$@" 2>>"$work/chromium.log"
}
title=$(run_chromium --dump-dom "file://$here/width.html#$index" | sed -n 's/.*<title>\([^<]*\)<.*/\1/p')
echo "index_check: $index in a 1400 px frame: $title"
sw=$(echo "$title" | sed -n 's/.*scrollWidth=\([0-9]*\).*/\1/p')
if [ -z "$sw" ]; then
  echo "index_check: FAIL: Chromium did not measure the page (see $work/chromium.log)"; exit 1
fi
if [ "$sw" -gt 1400 ]; then
  echo "index_check: FAIL: the page is $sw px wide: it scrolls sideways at 1400 px"; exit 1
fi
rm -f "$work/index.png"
run_chromium --window-size=1400,1000 --screenshot="$work/index.png" "file://$index" >/dev/null
if [ ! -s "$work/index.png" ]; then
  echo "index_check: FAIL: no screenshot (see $work/chromium.log)"; exit 1
fi
if [ ! -f "$baseline" ]; then
  mkdir -p "$(dirname "$baseline")" && cp "$work/index.png" "$baseline"
  echo "index_check: FAIL: no baseline: the candidate is $baseline (look at it, commit it)"; exit 1
fi
"$lamina" diff "$baseline" "$work/index.png" --out "$work/diff.png"
rc=$?
[ $rc -eq 0 ] && echo "index_check: the screenshot is the baseline's; fits 1400 px"
exit $rc
