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
local list = {}
for _, k in ipairs(order) do list[#list + 1] = series[k] end
lamina.plot{ file = png, width = 760, height = 560, legend = "top", yrange = { 0, 30 },
             title = "lamina bench engine: M particle-steps/s (" .. load .. ")",
             xlabel = "log10 particles", ylabel = "M particle-steps/s", series = list }
