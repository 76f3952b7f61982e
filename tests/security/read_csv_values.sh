#!/bin/sh
# read_csv_values.sh LAMINA - issue 31 item 8: lamina.read_csv took 1e999 as
# inf, and its refusal of a value that is not a number showed '(null)' (the
# message read the wrong stack slot). Now non-finite numbers are refused
# too, and the message shows the field as written.
lamina=$1 out=out/security/read_csv_values
rm -rf "$out"
mkdir -p "$out"
fail=0
check() {   # VALUE EXPECTED-MESSAGE
  printf 't,x\n0,1\n1,%s\n' "$1" > "$out/v.csv"
  printf 'lamina.read_csv("%s/v.csv")\n' "$out" > "$out/r.lua"
  "$lamina" run "$out/r.lua" > "$out/r.txt" 2>&1
  status=$?
  if [ $status -ne 2 ] || ! grep -F -q -- "$2" "$out/r.txt"; then
    echo "FAIL: value '$1': status $status, want 2 and '$2':"; cat "$out/r.txt"; fail=1
  fi
}
check 1e999 "'$out/v.csv' line 3, column 'x': '1e999' is not a finite number"
check nan "'$out/v.csv' line 3, column 'x': 'nan' is not a finite number"
check -inf "'$out/v.csv' line 3, column 'x': '-inf' is not a finite number"
check abc "'$out/v.csv' line 3, column 'x': 'abc' is not a finite number"
# a good file still reads
printf 't,x\n0,1\n1,-2.5e3\n' > "$out/v.csv"
printf 'local c, names, n = lamina.read_csv("%s/v.csv") assert(n == 2 and c.x[2] == -2500)\n' "$out" > "$out/r.lua"
"$lamina" run "$out/r.lua" > "$out/r.txt" 2>&1 || { echo "FAIL: a good file"; cat "$out/r.txt"; fail=1; }
exit $fail
