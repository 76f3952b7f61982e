#!/bin/sh
# run.sh - the verification matrix (issue 30 item 1): every case of
# tests/verify/*.lua on every documented combination of basis (linear,
# gimp, bspline2) x membrane force (point, segment; membranes only, the
# cases headed "-- verify: membrane") x scheme (musl, usl), plus the
# engine's default (no --set at all), at each level (resolution), two jobs
# at a time. Collects the cases' "verify ..." lines into a CSV and writes
# docs/verification.md (scripts/verify/report.py).
#
# usage: scripts/verify/run.sh [-l "1 2"] [-j 2] [-c "case1 case2"] [-o OUTDIR]
#                              [-b "bspline2"] [-m corrected] [-t apic]
#   -b limits the bases of the matrix; -m runs every job (the default row
#   too) with lamina.sim{mass = ...}, -t with lamina.sim{transfer = ...}
#   (docs/api.md; "apic" needs -b bspline2).
#   LAMINA (default build/lamina) is the binary; run from the repository.
set -eu
LAMINA=${LAMINA:-build/lamina}
LEVELS="1 2"
JOBS=2
CASES=""
OUT=build/verify
BASES="linear gimp bspline2"
MASS=""
TRANSFER=""
while getopts l:j:c:o:b:m:t: opt; do
  case $opt in
    l) LEVELS=$OPTARG ;;
    j) JOBS=$OPTARG ;;
    c) CASES=$OPTARG ;;
    o) OUT=$OPTARG ;;
    b) BASES=$OPTARG ;;
    m) MASS=$OPTARG ;;
    t) TRANSFER=$OPTARG ;;
    *) echo "usage: $0 [-l LEVELS] [-j JOBS] [-c CASES] [-o OUTDIR] [-b BASES] [-m MASS] [-t TRANSFER]" >&2; exit 2 ;;
  esac
done
[ -x "$LAMINA" ] || { echo "run.sh: no lamina at $LAMINA (build first, or set LAMINA)" >&2; exit 2; }
if [ -z "$CASES" ]; then
  CASES=$(for f in tests/verify/*.lua; do basename "$f" .lua; done)
fi
rm -rf "$OUT/jobs"
mkdir -p "$OUT/jobs"
list="$OUT/jobs.txt"
: > "$list"
for c in $CASES; do
  if grep -q '^-- verify: membrane' "tests/verify/$c.lua"; then forces="point segment"; else forces="-"; fi
  for l in $LEVELS; do
    echo "$c default default default $l" >> "$list"
    for b in $BASES; do
      for f in $forces; do
        for s in musl usl; do echo "$c $b $f $s $l" >> "$list"; done
      done
    done
  done
done
n=$(wc -l < "$list")
echo "run.sh: $n runs, $JOBS at a time, into $OUT" >&2
start=$(date +%s)
export LAMINA OUT MASS TRANSFER
xargs -P "$JOBS" -L 1 sh scripts/verify/job.sh < "$list"
end=$(date +%s)
echo "run.sh: $n runs in $((end - start)) s" >&2
python3 scripts/verify/report.py "$OUT" --seconds $((end - start)) --jobs "$JOBS"
