#!/bin/sh
# sweep_summary_markup.sh LAMINA SCRIPT - issue 31 item 8: a reported string
# went raw into sweep's summary.md (rendered as HTML by Markdown viewers)
# and onto the terminal (escape sequences). Now &lt; &gt; &amp;, '\|', and
# control characters as spaces.
lamina=$1 script=$2 out=out/security/sweep_markup
rm -rf "$out"
"$lamina" sweep "$script" --set v=1,2 --out "$out" > "$out.txt" 2>&1 ||
  { cat "$out.txt"; echo "FAIL: the sweep failed"; exit 1; }
fail=0
for f in "$out/summary.md" "$out.txt"; do
  if grep -q '<script>' "$f" || LC_ALL=C grep -q "$(printf '\033')" "$f"; then
    echo "FAIL: raw markup or escape in $f:"; od -c "$f" | head; fail=1
  fi
done
grep -F -q '&lt;script&gt;alert(1)&lt;/script&gt; \| a &amp; b  [2J end' "$out/summary.md" ||
  { echo "FAIL: the note is not escaped as expected:"; cat "$out/summary.md"; fail=1; }
exit $fail
