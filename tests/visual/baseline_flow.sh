#!/bin/sh
# baseline_flow.sh LAMINA SCENES BASELINES WORK
# The life of a baseline, in a scratch copy of BASELINES:
#   1. missing: --compare fails and writes the candidate where the baseline
#      belongs - byte for byte the committed baseline (rendering is
#      deterministic);
#   2. present: --compare passes;
#   3. --update-baselines rewrites only what fails: a wrong demo.png is
#      rewritten, the right two_disks.png (and every other scene's) keeps its
#      bytes and its time.
lamina=$1 scenes=$2 baselines=$3 work=$4
b=$work/baselines
rm -rf "$work" && mkdir -p "$b" || exit 2
fail=0
check() { if eval "$2"; then echo "ok: $1"; else echo "FAIL: $1" >&2; fail=1; fi; }

out=$("$lamina" gallery --compare --only demo --scripts "$scenes" --baselines "$b" \
      --work "$work/run1" 2>&1); rc=$?
echo "$out"
check "a missing baseline fails" "[ $rc -eq 1 ]"
check "... and says where the candidate went" \
      "echo \"\$out\" | grep -q 'no baseline; wrote the candidate to $b/demo.png'"
check "... which is the committed baseline, byte for byte" "cmp -s '$b/demo.png' '$baselines/demo.png'"
check "... with its state hash" "cmp -s '$b/demo.hash' '$baselines/demo.hash'"

"$lamina" gallery --compare --only demo --scripts "$scenes" --baselines "$b" --work "$work/run2"
check "the written baseline then passes" "[ $? -eq 0 ]"

# every other scene's right baseline, then the wrong picture for demo
n=0
for f in "$scenes"/*.lua; do
  s=$(basename "$f" .lua); n=$((n + 1))
  [ "$s" = demo ] && continue
  cp "$baselines/$s.png" "$baselines/$s.hash" "$b/" || exit 2
done
cp "$baselines/two_disks.png" "$b/demo.png"          # the wrong picture
touch -d '2001-01-01 00:00:00' "$b/two_disks.png"
out=$("$lamina" gallery --update-baselines --scripts "$scenes" --baselines "$b" \
      --work "$work/run3" 2>&1); rc=$?
echo "$out"
check "--update-baselines succeeds" "[ $rc -eq 0 ]"
check "... rewrites one of $n" "echo \"\$out\" | grep -q '$n baselines checked, 1 rewritten'"
check "... the failing one, back to the right picture" "cmp -s '$b/demo.png' '$baselines/demo.png'"
check "... and leaves the passing one alone" \
      "[ \"\$(stat -c %Y '$b/two_disks.png')\" = \"\$(date -d '2001-01-01 00:00:00' +%s)\" ]"
exit $fail
