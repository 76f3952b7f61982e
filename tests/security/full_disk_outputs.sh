#!/bin/sh
# Issue 31 item 6: on a full disk lamina.plot kept a PNG whose CSV failed,
# and a VTK series kept pieces its .pvd did not list. A plot is now complete
# or removed, and a VTK output's pieces go when its .pvd cannot be written.
# The full disk is a file size limit (ulimit -f, 512-byte blocks): writes
# past it fail with EFBIG (SIGXFSZ is handled as SIGTERM since issue 31).
# usage: full_disk_outputs.sh LAMINA
lamina=$1
dir=out/security/full_disk
rm -rf "$dir"; mkdir -p "$dir"
cat > "$dir/plot.lua" <<'LUA'
local x, y = {}, {}
for i = 1, 20000 do x[i] = i * 1.000000001; y[i] = math.sin(i) * 1.000000001 end
lamina.plot{ file = "out/security/full_disk/p.png", csv = true, width = 200, height = 150,
             series = { { x = x, y = y } } }
LUA
(ulimit -f 64; "$lamina" run "$dir/plot.lua" > "$dir/plot.out" 2>&1)
st=$?
fail=0
[ $st -ne 0 ] || { echo "FAIL: the plot's CSV of ~700 kB was written under a 32 kB limit"; fail=1; }
[ ! -e "$dir/p.png" ] || { echo "FAIL: the PNG stayed without its CSV"; ls -la "$dir"; fail=1; }
[ ! -e "$dir/p.csv" ] || { echo "FAIL: a partial CSV"; fail=1; }
ls "$dir" | grep -q "\.tmp\." && { echo "FAIL: temporaries left"; fail=1; }
# the same plot without the limit: both written
"$lamina" run "$dir/plot.lua" > "$dir/plot2.out" 2>&1 && [ -s "$dir/p.png" ] && [ -s "$dir/p.csv" ] ||
  { echo "FAIL: the plot without a limit"; cat "$dir/plot2.out"; fail=1; }
cat > "$dir/vtk.lua" <<'LUA'
local sim = lamina.sim{ dt = 1e-3, domain = {0, 0, 1, 1}, cell = 0.02 }
local el = lamina.elastic{ rho = 1000, E = 1000, nu = 0.3 }
sim:body{ material = el, region = lamina.disk{ center = {0.5, 0.5}, radius = lamina.param("r", 0.05) } }
sim:vtk{ file = "out/security/full_disk/series", every = 1e-3 }
sim:run{ t_end = 0.01 }
LUA
# the particles piece (16 kB) fits the 32 kB limit, the grid piece (146 kB) does not
(ulimit -f 64; "$lamina" run "$dir/vtk.lua" > "$dir/vtk.out" 2>&1)
st=$?
[ $st -ne 0 ] || { echo "FAIL: the VTK series was written under the limit"; fail=1; }
for f in "$dir"/series_*; do
  [ -e "$f" ] || continue
  [ -e "$dir/series.pvd" ] && grep -q "$(basename "$f")" "$dir/series.pvd" ||
    { echo "FAIL: $f is not listed by a .pvd"; fail=1; }
done
[ $fail -eq 0 ] && echo "ok: a failed plot or VTK output leaves nothing half-written"
cat "$dir/plot.out" "$dir/vtk.out" | grep -v "^stack\|^\s" | head -4
exit $fail
