-- Issue 36 item 1: Box 9's dog-bone at cell 0.05 with the page's scheme
-- (MUSL, quadratic B-spline, pure FLIP, point forces) and multi-rate
-- stepping, multirate = "impulse", the gas at 16 x the deck's dt
-- (docs/performance.md "The gas's step beside a membrane"). Without
-- lamina.sim{viscous_limit} a gas point rarefied to rho < 0.01 oscillates
-- with period two under its explicit viscous stress and inverts (t = 0.43);
-- with viscous_limit = 0.25 the run lives, and through the snap (the first
-- 0.3 time units, where every other sub-stepped form gained or lost) it
-- holds the plain step's numbers, computed here:
--   * without the limit the run stops before t = 0.5 (what the limit is for);
--   * with it, at t = 0.3: the total energy's change from the start within
--     1.5 x the plain step's (measured 2026-12-05: the plain step +1.786 of
--     118.49, the impulse run +2.069, 1.16 x), and the mean enclosed
--     pressure over [0.2, 0.3] within the page's tolerance 2.7 (the papers'
--     own difference, scripts/paper/gas_dogbone.lua) of the plain step's
--     (measured 31.70 against 32.12);
--   * the limit acted on few points: under 5 % of the gas at t = 0.3
--     (measured 0.54 %).
-- 14 CPU s, most of it the plain step's 8 571 steps (label slow).
-- To t = 8.5 (scripts/measure/dogbone_multirate.lua, 51 CPU s) the page's
-- radius, pressure, hoop against p r / t and mass stay within its
-- tolerances: docs/performance.md.
local b = require("dogbone_box9")
local h, d = 0.05, b.deck

local function build(m, limit)
  local sim = lamina.sim{ domain = {0, 0, d.width, d.width}, cell = h, dt = b.dt(h) * m, courant = 1.05,
                          boundary = { left = "symmetry", bottom = "symmetry", right = "symmetry", top = "symmetry" },
                          basis = "bspline2", substeps = m > 1 and "auto" or nil,
                          multirate = m > 1 and "impulse" or nil, viscous_limit = limit }
  local air = lamina.gas{ rho = d.rho_gas, e = d.e, gamma = d.gamma, mu = d.mu }
  local skin = lamina.membrane{ rho = d.rho_membrane, E = d.E, nu = d.nu, thickness = d.thickness,
                                law = "plane_stress", one_way = true }
  local gas = sim:body{ material = air, ppc = d.nprg, region = b.contains, name = "gas" }
  local mem = sim:membrane{ material = skin, name = "membrane", count = d.points, normals = "connectivity",
                            orient = {0, 0}, force = "point", curve = lamina.polyline(b.polyline()) }
  return sim, gas, mem
end

-- energy change at t_end and the mean pressure over [t_end - 0.1, t_end]
local function through_snap(m, limit, t_end)
  local sim, gas, mem = build(m, limit)
  local E0 = sim:energy().total
  local ps = {}
  sim:every(0.01, function(s) if s.t > t_end - 0.1 - 1e-9 then ps[#ps + 1] = gas:pressure(mem) end end)
  local ok, err = pcall(function() sim:run{ t_end = t_end } end)
  local pm = 0
  for _, p in ipairs(ps) do pm = pm + p / #ps end
  local g, n = gas:particles(), 0
  local below = limit and limit > 0 and d.mu * sim.dt / (limit * h * h) or 0
  for q = 1, #gas do if g.rho[q] < below then n = n + 1 end end
  return { ok = ok, err = err, t = sim.t, dE = sim:energy().total - E0, p = pm, limited = n / #gas }
end

local off = through_snap(16, nil, 0.5)
print(string.format("impulse, 16 x, no limit: %s at t = %.4f", off.ok and "reached" or "stopped", off.t))
assert(not off.ok, "impulse at 16 x without the limit reached t = 0.5: the check cannot tell")

local plain = through_snap(1, nil, 0.3)
local on = through_snap(16, 0.25, 0.3)
print(string.format("to t = 0.3: plain step dE %+.3f, pressure %.3f; impulse 16 x, viscous_limit 0.25: dE %+.3f "
                    .. "(%.2f x), pressure %.3f, limited %.2f %% of the gas", plain.dE, plain.p, on.dE,
                    on.dE / plain.dE, on.p, 100 * on.limited))
assert(plain.ok and on.ok, "a run stopped: " .. tostring(plain.err or on.err))
assert(math.abs(on.dE) <= 1.5 * math.abs(plain.dE),
       string.format("energy change %.3f against the plain step's %.3f", on.dE, plain.dE))
assert(math.abs(on.p - plain.p) <= 2.7, string.format("pressure %.3f against the plain step's %.3f", on.p, plain.p))
assert(on.limited < 0.05, string.format("the limit acted on %.1f %% of the gas", 100 * on.limited))
