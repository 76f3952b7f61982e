#!/bin/sh
# memory_cap.sh LAMINA SCRIPTS_DIR LIMIT_KB - issue 31 item 5: the engine's
# arrays, the renderer's canvases and the Lua heap count against one cap
# (src/util/lu_budget.c). Each run is under `ulimit -v LIMIT_KB` as a
# backstop, so that a cap that does not hold fails the test instead of
# taking the machine's memory (LIMIT_KB 0: no ulimit, for the sanitizers,
# which reserve terabytes of address space).
lamina=$1 dir=$2 limit=$3
out=out/security/memory_cap
rm -rf "$out"
mkdir -p "$out"
fail() { echo "FAIL: $*"; exit 1; }
# run NAME EXPECTED_STATUS LAMINA_ARGS... : stdout+stderr in $out/NAME.txt
run() {
  name=$1 want=$2
  shift 2
  if [ "$limit" != 0 ]; then
    (ulimit -v "$limit" && exec "$lamina" "$@") > "$out/$name.txt" 2>&1
  else
    "$lamina" "$@" > "$out/$name.txt" 2>&1
  fi
  got=$?
  [ $got -eq "$want" ] || { cat "$out/$name.txt" | head -c 2000; fail "$name: exit status $got, want $want"; }
}
has() { grep -qF -- "$2" "$out/$1.txt" || { head -c 2000 "$out/$1.txt"; fail "$1: no '$2'"; }; }

# 2000 kept simulations: stopped at the cap (256 MB: the fourth grid),
# naming the cap, each part, and how to raise it
run sims_kept 2 run --memory 256 "$dir/memory_sims.lua" --set n=2000 --set keep=1
has sims_kept "lamina.sim: cannot make a 1000 x 1000 grid: memory limit 256 MB reached (engine: 2"
has sims_kept ", lua: 0 MB, render: 0 MB; engine asked for 8 MB more)"
has sims_kept "LAMINA_MEMORY_MB=N or lamina run --memory N raises it"
# dropped ones are collected before the cap refuses (300 x 72 MB = 21 GB
# made in all); the cap from the environment this time
LAMINA_MEMORY_MB=256 run sims_dropped 0 run "$dir/memory_sims.lua" --set n=300 --set keep=0
has sims_dropped "made 300"

# 100 kept figures of 16384^2 (1 GiB each): the second is refused
run figures_kept 2 run --memory 1100 "$dir/memory_figures.lua" --set n=100 --set keep=1
has figures_kept "lamina.figure: cannot create a 16384 x 16384 canvas: memory limit 1100 MB reached (engine: 0 MB, lua: 0 MB, render: 1024 MB; render asked for 1024 MB more)"
# dropped ones are collected (40 x 64 MB past a 200 MB cap)
run figures_dropped 0 run --memory 200 "$dir/memory_figures.lua" --set n=40 --set size=4096 --set keep=0
has figures_dropped "made 40"

# the Lua heap counts too: with 69 MB of engine arrays it reaches a 128 MB
# cap long before its own 1024 MB one
run lua_and_engine 2 run --memory 128 "$dir/memory_lua_and_engine.lua"
has lua_and_engine "memory_lua_and_engine.lua: memory limit 128 MB reached (engine: 69 MB, lua: "
has lua_and_engine "; lua asked for"
if grep -q "Lua memory reached its cap" "$out/lua_and_engine.txt"; then fail "lua_and_engine: blamed on --lua-mem"; fi

# bad caps refused by name
LAMINA_MEMORY_MB=lots run env_bad 2 run "$dir/memory_sims.lua" --set n=1
has env_bad "LAMINA_MEMORY_MB='lots': needs a size in MB from 16 to 1048576 (default 4096)"
run arg_bad 2 run --memory 0 "$dir/memory_sims.lua" --set n=1
has arg_bad "--memory needs a size in MB from 16 to 1048576"
exit 0
