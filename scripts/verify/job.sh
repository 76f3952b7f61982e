#!/bin/sh
# job.sh CASE BASIS FORCE SCHEME LEVEL - one run of the verification matrix
# (scripts/verify/run.sh): its stdout, stderr, exit status and wall time go
# to $OUT/jobs/. BASIS "default" runs the case with no --set of basis, force
# or scheme (the engine's defaults); FORCE "-" for a case without membranes.
c=$1 b=$2 f=$3 s=$4 l=$5
id="$c.$b.$f.$s.$l"
set -- run "tests/verify/$c.lua" --quiet --set level="$l"
[ "$b" = default ] || set -- "$@" --set basis="$b" --set scheme="$s"
[ "$f" = - ] || [ "$f" = default ] || set -- "$@" --set force="$f"
[ -z "${MASS:-}" ] || set -- "$@" --set mass="$MASS"
[ -z "${TRANSFER:-}" ] || set -- "$@" --set transfer="$TRANSFER"
t0=$(date +%s.%N)
st=0
nice "$LAMINA" "$@" > "$OUT/jobs/$id.out" 2> "$OUT/jobs/$id.err" || st=$?
t1=$(date +%s.%N)
printf "%s %s %s %s %s %s %s\n" "$c" "$b" "$f" "$s" "$l" "$st" \
  "$(awk "BEGIN { printf \"%.2f\", $t1 - $t0 }")" > "$OUT/jobs/$id.meta"
