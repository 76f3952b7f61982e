#!/bin/sh
# Every file in scripts/examples is a template (issue 35 item 6): copied
# alone into an empty folder elsewhere, it runs with nothing but lamina -
# lamina's Lua library (assets/lua) hidden (LAMINA_ASSETS names a copy of
# assets/ that has only the fonts), no sibling script beside it - for a
# short time (every example takes --set t_end), exits 0 and writes its
# output under the folder it runs in.
. "$(dirname "$0")/lib.sh"
EXAMPLES=$SRC/../../scripts/examples
mkdir -p assets || exit 1
ln -s "$(cd "$SRC/../../assets/fonts" && pwd)" assets/fonts
n=0
for script in "$EXAMPLES"/*.lua; do
  name=$(basename "$script" .lua)
  mkdir -p "$name" && cp "$script" "$name/" || exit 1
  (cd "$name" && LAMINA_ASSETS="$W/assets" "$LAMINA" run "$name.lua" --set t_end=0.01 \
     > out.txt 2> err.txt)
  st=$?
  if [ $st -ne 0 ]; then
    echo "FAIL: $name.lua copied alone: exit status $st"
    show "$name/err.txt"
    fail=1
  fi
  check_not "$name/err.txt" "module '.*' not found|cannot read"
  files=$(find "$name/out" -type f 2>/dev/null | wc -l)
  [ "$files" -ge 1 ] || { echo "FAIL: $name.lua wrote nothing under out/"; fail=1; }
  echo "$name.lua: exit $st, $files files written"
  n=$((n + 1))
done
[ $n -ge 3 ] || { echo "FAIL: $n examples found in $EXAMPLES"; fail=1; }
exit $fail
