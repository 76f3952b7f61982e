#!/bin/sh
# Issue 31 item 2: `lamina sweep --slurm` put the script's name and the
# --slurm path unquoted into the sbatch script, and a name with a newline
# broke out of its comment header: its second line ran. A name (script,
# --slurm file, --set value) with a newline or a quote is now refused, for
# --slurm and --emit-jobs alike, and nothing is written; other names are
# quoted (sw_shell_quote) and run as they are.
# usage: sweep_names.sh LAMINA
set -u
lamina=$1
dir=out/security/sweep_names
rm -rf "$dir"; mkdir -p "$dir"
src="$dir/plain.lua"   # copied under odd names
echo 'print("E = " .. lamina.param("E", 1))' > "$src"
nl='
'
bad1="$dir/a${nl}touch PWNED${nl}#.lua"
bad2="$dir/q'x.lua"
cp "$src" "$bad1"; cp "$src" "$bad2"
fail=0
for s in "$bad1" "$bad2"; do
  for mode in "--slurm $dir/array.sbatch" --emit-jobs; do
    # shellcheck disable=SC2086
    "$lamina" sweep "$s" --set E=1000 --out "$dir/runs" $mode > "$dir/out.txt" 2> "$dir/err.txt"
    st=$?
    [ $st -eq 2 ] || { echo "FAIL: $mode with a bad name: status $st"; fail=1; }
    grep -q "refused, it would go into a shell line" "$dir/err.txt" || {
      echo "FAIL: $mode: no clear refusal:"; cat "$dir/err.txt"; fail=1; }
    [ ! -s "$dir/out.txt" ] && [ ! -e "$dir/array.sbatch" ] && [ ! -e "$dir/array.sbatch.jobs" ] || {
      echo "FAIL: $mode wrote something"; fail=1; }
  done
done
# a --slurm path with a newline is refused too
"$lamina" sweep "$src" --set E=1000 --out "$dir/runs" --slurm "$dir/x${nl}y.sbatch" 2> "$dir/err.txt"
[ $? -eq 2 ] && grep -q "refused" "$dir/err.txt" || { echo "FAIL: --slurm path with a newline"; fail=1; }
# a name with spaces, ; and $ is quoted: the array task runs it as it is
odd="$dir/odd \$(touch PWNED); x.lua"
cp "$src" "$odd"
"$lamina" sweep "$odd" --set E=1000 --out "$dir/runs" --slurm "$dir/array.sbatch" 2> "$dir/err.txt" ||
  { echo "FAIL: --slurm with a quotable name"; cat "$dir/err.txt"; fail=1; }
(cd "$dir" && SLURM_ARRAY_TASK_ID=0 bash array.sbatch > task.out 2>&1) ||
  { echo "FAIL: the array task"; cat "$dir/task.out"; fail=1; }
grep -q "^status 0" "$dir"/runs/*/run.txt || { echo "FAIL: the run did not happen"; fail=1; }
for p in PWNED "$dir/PWNED"; do [ ! -e "$p" ] || { echo "FAIL: $p created"; fail=1; }; done
[ $fail -eq 0 ] && echo "ok: bad names refused, odd names quoted"
exit $fail
