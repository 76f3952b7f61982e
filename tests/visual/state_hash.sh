#!/bin/sh
# state_hash.sh LAMINA SCRIPT HASHFILE OUT
# The simulation alone, no pictures compared: runs SCRIPT with the --set
# parameters of its "-- visual:" header line (as `lamina gallery --compare`
# does) and compares the state_hash it reports (lamina.report, sim:hash())
# with the first line of HASHFILE. Beside the picture test of the same
# scene, it tells a simulation change (this fails) from a drawing change
# (this passes, the picture test fails).
lamina=$1 script=$2 hashfile=$3 out=$4
sets=$(sed -n 's/^-- visual: *//p' "$script")
args=""
for s in $sets; do args="$args --set $s"; done
# shellcheck disable=SC2086 # the words of the header are separate arguments
got=$("$lamina" run "$script" --set out="$out" $args --quiet | sed -n 's/^report: state_hash = //p')
want=$(head -n 1 "$hashfile" 2>/dev/null)
if [ -z "$got" ]; then
  echo "FAIL: $script reported no state_hash (or did not run)" >&2; exit 1
fi
if [ -z "$want" ]; then
  echo "FAIL: no baseline $hashfile (the state hash is $got)" >&2; exit 1
fi
if [ "$got" != "$want" ]; then
  echo "FAIL: the simulation changed: state hash $got, baseline $want ($hashfile)" >&2; exit 1
fi
echo "the simulation is unchanged: state hash $got after$args"
