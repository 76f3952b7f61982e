#!/bin/sh
# gallery_jobs.sh LAMINA SCRIPTS WORK - `lamina gallery --jobs N`
# (gallery_queue.c): figures run several at once make the same figures as
# one at a time, byte for byte (images, values, state hashes; only the run
# times differ), and the queue starts the costliest first by the last run's
# meta.json (a figure never run before all others).
lamina=$1 scripts=$2 work=$3
rm -rf "$work" && mkdir -p "$work/one" "$work/two" || exit 2
fail=0
# the last runs' costs, made up: frame_options 3 s, revolve 2 s, demo 1 s
# of processor time; two_disks has none. One at a time, the order is then
# two_disks, frame_options, revolve, demo.
for f in demo:1 frame_options:3 revolve:2; do
  mkdir -p "$work/one/g/${f%:*}" &&
    printf '{"status": 0, "seconds": 99, "cpu_seconds": %s}\n' "${f#*:}" > "$work/one/g/${f%:*}/meta.json"
done
# the same relative gallery folder in both, so that the PNGs' provenance
# (their --set out=...) is the same too
(cd "$work/one" && "$lamina" gallery --force --jobs 1 --scripts "$scripts" --gallery g) > "$work/one.txt" 2>&1 ||
  { cat "$work/one.txt"; echo "FAIL: --jobs 1 failed"; exit 1; }
(cd "$work/two" && "$lamina" gallery --force --jobs 2 --scripts "$scripts" --gallery g) > "$work/two.txt" 2>&1 ||
  { cat "$work/two.txt"; echo "FAIL: --jobs 2 failed"; exit 1; }
cat "$work/one.txt" "$work/two.txt"
order=$(sed -n 's/^gallery: \([a-z_]*\): [0-9.]* s, .*/\1/p' "$work/one.txt" | tr '\n' ' ')
[ "$order" = "two_disks frame_options revolve demo " ] ||
  { echo "FAIL: --jobs 1 ran them in the order '$order', not costliest first"; fail=1; }
grep -q '^gallery: 4 runs: [0-9.]* s of processor time in [0-9.]* s, up to 2 at once$' "$work/two.txt" ||
  { echo "FAIL: no line with the runs' processor and wall time"; fail=1; }
n=0
for m in "$work"/one/g/*/meta.json; do
  d=${m%/meta.json}; name=${d##*/}; n=$((n + 1))
  grep -q '"cpu_seconds": [0-9]' "$m" || { echo "FAIL: $name: no cpu_seconds in meta.json"; fail=1; }
  # everything but the times
  grep -v '"seconds"\|"cpu_seconds"' "$m" > "$work/a.json"
  grep -v '"seconds"\|"cpu_seconds"' "$work/two/g/$name/meta.json" > "$work/b.json"
  cmp -s "$work/a.json" "$work/b.json" || { echo "FAIL: $name: meta.json differs:"; diff "$work/a.json" "$work/b.json"; fail=1; }
  for f in "$d"/*.png "$d"/*.csv; do
    [ -e "$f" ] || continue
    cmp -s "$f" "$work/two/g/$name/${f##*/}" || { echo "FAIL: $name/${f##*/} differs with --jobs 2"; fail=1; }
  done
done
[ $n -eq 4 ] || { echo "FAIL: $n figures, expected 4"; fail=1; }
[ $fail -eq 0 ] && echo "ok: $n figures the same with --jobs 1 and 2, costliest first"
exit $fail
