-- bench_plot.lua - the plot of scripts/measure/bench_plot.sh: million
-- particle-steps per second (wall clock) against particle count, one curve
-- per case and thread count, log-log.
local csv = lamina.param("csv", "out/bench_plot/bench.csv")
local png = lamina.param("png", "out/bench_plot/bench_engine.png")
local load = lamina.param("load", "")
local t = lamina.read_csv(csv)
local names = { "disks MUSL", "disks USL", "disks release", "gas+membrane", "gas+isosurf" }
local series, order = {}, {}
for i = 1, #t.particles do
  local key = string.format("%s, %d thread%s", names[t.case[i]], t.threads[i], t.threads[i] == 1 and "" or "s")
  if not series[key] then
    -- one colour per case, dashed for two threads
    series[key] = { x = {}, y = {}, label = key, color = t.case[i], dashed = t.threads[i] > 1 }
    order[#order + 1] = key
  end
  local s = series[key]
  s.x[#s.x + 1] = math.log(t.particles[i], 10)
  s.y[#s.y + 1] = t.mps[i]
end
local list, top = {}, 0
for _, k in ipairs(order) do
  list[#list + 1] = series[k]
  for _, y in ipairs(series[k].y) do top = math.max(top, y) end
end
-- room above the fastest curve for the legend, which would hide curves
-- beside them
top = 10 * math.ceil(1.6 * top / 10)
lamina.plot{ file = png, width = 760, height = 600, legend = "top", yrange = { 0, top },
             title = "lamina bench engine: M particle-steps/s (" .. load .. ")",
             xlabel = "log10 particles", ylabel = "M particle-steps/s", series = list }
