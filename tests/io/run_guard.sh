#!/bin/sh
# run_guard.sh LAMINA SCENE OUT - issue 33 item 4: every way out of a run
# (callback error, pin velocity function error, checkpoint write failure,
# Courant refusal, engine failure, SIGTERM) exits with its documented
# status and message and writes the recorder's CSV up to the failure; under
# pcall the next sim:step runs (tests/io/run_guard/scene.lua).
L=$1 S=$2 O=$3
rc=0
fail() { echo "FAIL: $*"; rc=1; }

# csv DIR MIN MAX: the CSV exists with its header and MIN..MAX rows
csv() {
  [ -f "$1/rec.csv" ] || { fail "$1/rec.csv was not written"; return; }
  head -1 "$1/rec.csv" | grep -q '^t,step,x' || fail "$1/rec.csv has no header"
  rows=$(($(wc -l < "$1/rec.csv") - 1))
  [ "$rows" -ge "$2" ] && [ "$rows" -le "$3" ] ||
    fail "$1/rec.csv has $rows rows, expected $2 to $3"
}

# case WAY CAUGHT STATUS PATTERN MINROWS MAXROWS
case_() {
  d=$O/$1_$2
  rm -rf "$d"; mkdir -p "$d"
  [ "$1" = checkpoint ] && : > "$d/not_a_folder"   # a file where the folder would be
  "$L" run "$S" --quiet --set way=$1 --set caught=$2 --set out="$d" >"$d/stdout" 2>"$d/stderr"
  got=$?
  [ "$got" = "$3" ] || fail "$1 caught=$2: exit status $got, expected $3"
  grep -Eq -- "$4" "$d/stderr" "$d/stdout" || fail "$1 caught=$2: no /$4/ in its output"
  if [ "$2" = true ]; then
    grep -q "stepped on at t = " "$d/stdout" || fail "$1 caught=$2: the next sim:step failed"
  fi
  csv "$d" "$5" "$6"
  ls "$d" | grep -q '\.tmp\.' && fail "$1 caught=$2: temporary files left: $(ls "$d")"
  echo "$1 caught=$2: exit $got, $(($(wc -l < "$d/rec.csv" 2>/dev/null || echo 1) - 1)) rows"
  [ $rc -eq 0 ] || { cat "$d/stderr" "$d/stdout"; }
}

for c in false true; do
  if [ $c = true ]; then ok=0; else ok=; fi
  case_ callback $c ${ok:-2} 'a callback failed' 6 6
  case_ pin $c ${ok:-2} 'the pin function failed at t = 0\.0505' 6 6
  case_ checkpoint $c ${ok:-2} 'sim:checkpoint: .*not_a_folder' 6 6
  case_ refused $c ${ok:-2} 'dt = 0\.001 is too large: Courant number' 6 6
  case_ unstable $c ${ok:-1} 'simulation failed: ' 1 1
done

# SIGTERM: stops at a step boundary, writes the records, exits 143 (128 +
# 15) even when the script caught the error and stepped on (docs/api.md)
for c in false true; do
  d=$O/signal_$c
  rm -rf "$d"; mkdir -p "$d"
  "$L" run "$S" --quiet --set way=signal --set caught=$c --set out="$d" >"$d/stdout" 2>"$d/stderr" &
  pid=$!
  i=0
  while [ ! -f "$d/started.png" ]; do
    i=$((i + 1)); [ $i -gt 600 ] && { fail "signal: the run did not start"; kill -9 $pid; exit 1; }
    sleep 0.1
  done
  sleep 0.3
  kill -TERM $pid
  wait $pid
  got=$?
  [ "$got" = 143 ] || fail "signal caught=$c: exit status $got, expected 143"
  grep -q "interrupted (SIGTERM) at t = " "$d/stderr" "$d/stdout" || fail "signal caught=$c: no message"
  [ $c = true ] && { grep -q "stepped on at t = " "$d/stdout" || fail "signal caught=true: the next sim:step failed"; }
  csv "$d" 1 1000000
  echo "signal caught=$c: exit $got, $(($(wc -l < "$d/rec.csv" 2>/dev/null || echo 1) - 1)) rows"
  [ $rc -eq 0 ] || cat "$d/stderr" "$d/stdout"
done
exit $rc
