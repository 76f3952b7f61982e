-- dogbone_gas_speeds.lua - where the dog-bone's fast gas points are (issue
-- 36 item 1, docs/performance.md "Multi-rate stepping"): Box 9's dog-bone
-- at cell 0.05 (quadratic B-spline, pure FLIP, two threads, as
-- dogbone_substeps.lua), every `every` time units the gas points' speeds
-- |v_p| split by their distance d to the nearest membrane point (d < 1
-- cell: "near"; the rest "far"): median, 90th and 99th percentile and the
-- largest, and the membrane points' own; the Courant number the fastest
-- gas point gives at the gas's step, dt (c_gas + |v|) / h.
--   lamina run scripts/measure/dogbone_gas_speeds.lua --set k=4 [--set t_end=0.2]
local b = require("dogbone_box9")
local k = lamina.param("k", 0)
local t_end = lamina.param("t_end", 0.2)
local every = lamina.param("every", 0.02)
local opts = { basis = "bspline2", threads = lamina.param("threads", 2),
               substeps = k > 0 and k or nil }
local h = 0.05
local sim, gas, mem = b.setup(h, opts)

local function pct(t, f)
  if #t == 0 then return 0 end
  return t[math.max(1, math.min(#t, math.floor(f * #t + 0.5)))]
end

local function sample(s)
  local g, m = gas:particles(), mem:particles()
  -- the membrane points binned by cell, to find each gas point's nearest
  local bins = {}
  local function key(i, j) return i * 4096 + j end
  for q = 1, #mem do
    local kk = key(math.floor(m.x[q] / h), math.floor(m.y[q] / h))
    local l = bins[kk]; if not l then l = {}; bins[kk] = l end
    l[#l + 1] = q
  end
  local near, far, cmax = {}, {}, 0
  for q = 1, #gas do
    local x, y = g.x[q], g.y[q]
    local i, j = math.floor(x / h), math.floor(y / h)
    local d2 = math.huge
    for di = -1, 1 do for dj = -1, 1 do
      local l = bins[key(i + di, j + dj)]
      if l then for _, r in ipairs(l) do
        local dx, dy = m.x[r] - x, m.y[r] - y
        local e = dx * dx + dy * dy
        if e < d2 then d2 = e end
      end end
    end end
    local v = math.sqrt(g.vx[q] ^ 2 + g.vy[q] ^ 2)
    if d2 < h * h then near[#near + 1] = v else far[#far + 1] = v end
  end
  local ms = {}
  for q = 1, #mem do ms[q] = math.sqrt(m.vx[q] ^ 2 + m.vy[q] ^ 2) end
  table.sort(near); table.sort(far); table.sort(ms)
  local vmax = math.max(near[#near] or 0, far[#far] or 0)
  local c = math.sqrt(1.4 * 0.4 * 250)   -- the gas's sound speed at the start (e = 250)
  print(string.format("t %.3f  near (%4d): %6.1f %6.1f %6.1f %6.1f | far (%5d): %6.1f %6.1f %6.1f %6.1f | "
    .. "membrane %6.1f %6.1f | Courant %.3f", s.t, #near, pct(near, 0.5), pct(near, 0.9), pct(near, 0.99),
    near[#near] or 0, #far, pct(far, 0.5), pct(far, 0.9), pct(far, 0.99), far[#far] or 0,
    pct(ms, 0.5), ms[#ms], s.dt * (c + vmax) / h))
end
print(string.format("dog-bone cell 0.05, substeps %d, dt %.4g: gas speeds (median, 90 %%, 99 %%, max)", k, sim.dt))
sample(sim)
sim:every(every, sample)
local clock = lamina.clock()
local ok, err = pcall(function() sim:run{ t_end = t_end } end)
print(string.format("%s at t = %.4f after %d steps, %.1f s%s", ok and "ended" or "stopped", sim.t, sim.nstep,
                    lamina.clock() - clock, ok and "" or (": " .. tostring(err))))
