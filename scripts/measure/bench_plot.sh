#!/bin/sh
# bench_plot.sh - issue 17 item 7: particle-steps per second against
# particle count, per case and thread count, as docs/img/bench_engine.png
# (docs/performance.md "The plot"). Runs `lamina bench engine` at 10^3 to
# 10^6 particles on one and two threads, turns its Markdown tables into one
# CSV, and plots it with lamina.plot. Usage, from the repository:
#   sh scripts/measure/bench_plot.sh [build/lamina]
set -eu
lamina=${1:-build/lamina}
out=out/bench_plot
mkdir -p "$out"
# lamina.read_csv reads numbers: the case as its row in bench_plot.lua's list
echo "case,particles,threads,mps" > "$out/bench.csv"
for t in 1 2; do
  "$lamina" bench engine --sizes 1e3,1e4,1e5,1e6 --threads "$t" | tee "$out/threads$t.md" |
    awk -F'|' -v t="$t" 'BEGIN { n["disks MUSL"] = 1; n["disks USL"] = 2
      n["disks release"] = 3; n["gas+membrane"] = 4; n["gas+isosurf"] = 5 }
      $3 ~ /^ *[0-9]+ *$/ {
      gsub(/^ +| +$/, "", $2); gsub(/ /, "", $3); gsub(/ /, "", $6)
      if ($2 in n) print n[$2] "," $3 "," t "," $6 }' >> "$out/bench.csv"
done
uptime | sed 's/.*load average/load average/' > "$out/load.txt"
"$lamina" run scripts/measure/bench_plot.lua --set csv="$out/bench.csv" \
  --set load="$(cat "$out/load.txt")" --set png=docs/img/bench_engine.png
