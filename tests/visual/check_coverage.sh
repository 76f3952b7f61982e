#!/bin/sh
# check_coverage.sh LAMINA SCENES GALLERY WORK
# The papers' coverage (SCRIPTS/coverage.tsv, docs/gallery.md "Coverage")
# must not go stale: copies the test scenes to WORK/scripts, has demo.lua's
# source cite [T] Figs 31-33, Table 5 and [F] Tables V-VI, writes a
# coverage.tsv that gets it wrong in each way the check must catch, and runs
# `lamina gallery --check` against the scenes' GALLERY: it must exit 1
# naming every problem. (demo.lua's changed header also makes it "changed
# since its figure was made"; that is not what is tested here.)
lamina=$1 scenes=$2 gallery=$3 work=$4
rm -rf "$work" && mkdir -p "$work/scripts" && cp "$scenes"/*.lua "$work/scripts/" || exit 2
sed -i "s/^-- source: /-- source: York's dissertation, Figs 31-33 and Table 5; [F] Tables V-VI; /" \
    "$work/scripts/demo.lua" || exit 2
T=$(printf '\t')
cat > "$work/scripts/coverage.tsv" <<TSV
# a broken coverage table
paper${T}item${T}caption${T}status${T}pages${T}note
T${T}Fig 31${T}initial conditions${T}reproduced${T}demo${T}
T${T}Fig 32${T}20 points${T}reproduced${T}two_disks${T}
T${T}Table 5${T}results${T}partial${T}demo, ghost${T}
F${T}Table V${T}airbag parameters${T}reproduced${T}demo${T}
F${T}Table V${T}airbag parameters again${T}reproduced${T}demo${T}
X${T}Fig 1${T}no such paper${T}missing${T}-${T}a diagram
M${T}Fig 2${T}a diagram${T}missing${T}-${T}
TSV
err=$("$lamina" gallery --check --scripts "$work/scripts" --gallery "$gallery" 2>&1)
rc=$?
echo "$err"
fail=0
[ $rc -eq 1 ] || { echo "FAIL: exit status $rc, expected 1" >&2; fail=1; }
for want in "demo.lua: its source cites [T] Fig 32, whose row in coverage.tsv does not name this page" \
            "demo.lua: its source cites [T] Fig 33, which coverage.tsv does not list" \
            "demo.lua: its source cites [F] Table VI, which coverage.tsv does not list" \
            "[T] Table 5 is partial: its note must say what is missing" \
            "[T] Table 5 names the page ghost, which has no script" \
            "[F] Table V is listed twice" \
            "coverage.tsv:8: not a row" \
            "[M] Fig 2 is missing: its note must say what lamina would need" \
            "revolve.lua: no row of" \
            "README.md: its coverage section is not"; do
  case "$err" in
    *"$want"*) ;;
    *) echo "FAIL: the check did not report: $want" >&2; fail=1 ;;
  esac
done
case "$err" in
  *"cites [T] Fig 31"*|*"cites [F] Table V,"*) echo "FAIL: a covered citation was reported" >&2; fail=1 ;;
esac
exit $fail
