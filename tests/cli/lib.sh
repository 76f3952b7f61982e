# lib.sh - shared by the workbench tests (sourced). Every wait is bounded
# and generous: the tests must pass on a loaded two-core machine, and a hang
# must become a failure, not a stuck test run.
LAMINA=$1
SRC=$2
NAME=$(basename "$0" .sh)
W=$(pwd)/cli_$NAME
rm -rf "$W"
mkdir -p "$W" || exit 1
cd "$W" || exit 1
fail=0

# check FILE PATTERN: FILE has a line matching the extended regex.
check() {
  if ! grep -Eq -- "$2" "$1"; then
    echo "FAIL: $1 has no line matching /$2/"
    fail=1
  fi
}

# check_not FILE PATTERN
check_not() {
  if grep -Eq -- "$2" "$1"; then
    echo "FAIL: $1 has a line matching /$2/"
    fail=1
  fi
}

# wait_for FILE PATTERN [SECONDS]: until FILE matches, at most SECONDS (60).
wait_for() {
  n=0
  limit=$(( ${3:-60} * 10 ))
  while ! grep -Eq -- "$2" "$1" 2>/dev/null; do
    n=$((n + 1))
    if [ $n -ge $limit ]; then
      echo "FAIL: waited ${3:-60} s for /$2/ in $1"
      fail=1
      return 1
    fi
    sleep 0.1
  done
  return 0
}

# wait_exit PID [SECONDS]: waits for a background process, killing it after
# SECONDS (60); its exit status in $status.
wait_exit() {
  n=0
  limit=$(( ${2:-60} * 10 ))
  while kill -0 "$1" 2>/dev/null; do
    n=$((n + 1))
    if [ $n -ge $limit ]; then
      echo "FAIL: process $1 still running after ${2:-60} s; killed"
      kill -9 "$1" 2>/dev/null
      fail=1
      break
    fi
    sleep 0.1
  done
  wait "$1"
  status=$?
}

# show FILE...: the files, for a failure's log.
show() {
  for f in "$@"; do
    echo "--- $f"
    cat "$f"
  done
}
