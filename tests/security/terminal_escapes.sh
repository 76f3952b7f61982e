#!/bin/sh
# terminal_escapes.sh LAMINA SCRIPT - issue 31 item 8: no control character
# a script writes reaches the terminal raw (print, io.write, lamina.report,
# the error message); each is shown as a Lua escape. Tab and newline pass,
# and so does other UTF-8 (é, €).
lamina=$1 script=$2
out=out/security/terminal_escapes
mkdir -p "$out"
"$lamina" run "$script" > "$out/stdout" 2> "$out/stderr"
status=$?
[ $status -eq 2 ] || { echo "FAIL: exit status $status (want 2: the script's error)"; exit 1; }
for f in stdout stderr; do
  # ESC, BEL, CR, BS, DEL; NUL; the C1 byte pair C2 9B (CSI)
  if LC_ALL=C grep -q "$(printf '[\033\007\015\010\177]')" "$out/$f" ||
     [ "$(tr -d '\000' < "$out/$f" | wc -c)" -ne "$(wc -c < "$out/$f")" ] ||
     LC_ALL=C grep -q "$(printf '\302\233')" "$out/$f"; then
    echo "FAIL: a raw control character on $f:"; od -c "$out/$f" | head -20; exit 1
  fi
done
want='a\27]52;c;ZXZpbA==\7b\27]0;owned\7c\27[2Jd\u{9b}e\13\8\0f\127g'
# (a reported string and an error message end at their NUL: C strings)
for what in "print:	$want	é€" "io.write: $want" 'report: value = a\27]52;c;ZXZpbA==\7b\27]0;owned\7c\27[2Jd\u{9b}e\13\8'; do
  grep -qF -- "$what" "$out/stdout" || { printf 'FAIL: no %s on stdout\n' "$what"; cat "$out/stdout"; exit 1; }
done
grep -qF -- 'lamina: error: a\27]52;c;ZXZpbA==\7b\27]0;owned\7c\27[2Jd\u{9b}e\13\8' "$out/stderr" || { echo "FAIL: the error message"; cat "$out/stderr"; exit 1; }
exit 0
