#!/bin/sh
# expect.sh STATUS PATTERN [PATTERN ...] -- COMMAND [ARG ...]
# Runs COMMAND and passes when it exits with STATUS and its stderr matches
# every (extended) regular expression PATTERN; a PATTERN written !REGEX must
# match no line (a scene the suite passes must not be warned of, issue 30
# item 2) and one written =REGEX exactly one (a warning said once a process). Used by the bad-input tests: a wrong input must fail with the
# right status and a message that says why.
want=$1; shift
n=0
while [ "$1" != "--" ]; do
  n=$((n + 1)); eval "pat_$n=\$1"; shift
  [ $# -eq 0 ] && { echo "expect.sh: missing --" >&2; exit 2; }
done
shift
err=$(mktemp)
"$@" >/dev/null 2>"$err"
got=$?
cat "$err"
rc=0
if [ "$got" != "$want" ]; then
  echo "FAIL: exit status $got, expected $want" >&2; rc=1
fi
i=1
while [ $i -le $n ]; do
  eval "p=\$pat_$i"
  case $p in
    !*)
      if grep -Eq -- "${p#!}" "$err"; then
        echo "FAIL: stderr matches /${p#!}/, which it must not" >&2; rc=1
      fi ;;
    =*)
      c=$(grep -Ec -- "${p#=}" "$err")
      if [ "$c" != 1 ]; then
        echo "FAIL: stderr matches /${p#=}/ on $c lines, not once" >&2; rc=1
      fi ;;
    *)
      if ! grep -Eq -- "$p" "$err"; then
        echo "FAIL: stderr does not match /$p/" >&2; rc=1
      fi ;;
  esac
  i=$((i + 1))
done
rm -f "$err"
exit $rc
