-- Issue 36 item 1: multi-rate stepping with scheme = "usl", the form that
-- carries Box 9's dog-bone at cell 0.05 to t = 8.5 with the gas at 16 times
-- the deck's dt (docs/performance.md "Multi-rate stepping"). With USL every
-- strain comes from the grid's velocities as the step leaves them (the gas's
-- from its mean nodal velocity over the step, X_i / dt), no re-map of the
-- gas's FLIP velocities; what it must hold:
-- 1. the walled string (assets/lua/string_modes.lua, segment forces,
--    quadratic B-spline, cell 1/32), mode 1 with 4 sub-steps of 0.4 h / c:
--    within 1 % of f_1 = (1 / 2L) sqrt(T / mu), and within 0.1 % of the
--    plain USL step's;
-- 2. the gas-filled quarter circle in equilibrium (tests/physics/substeps.lua's,
--    cell 0.1, p = 1000) with the gas at 10 times the plain step: radius
--    within 0.2 %, hoop stress within 1 % over 0.05, sigma t = p r within
--    1 % at the end, no gas out;
-- 3. the same circle started unstretched (it rings; substeps_energy.lua's
--    case): the total energy with 4 and 10 sub-steps grows no more than the
--    plain MUSL step's (USL's transfer dissipates: it may fall);
-- 4. deterministic: the same run twice, the same hash.
-- Measured 2026-12-05: see the printed lines (docs/performance.md).
local sm = require("string_modes")
local cm = require("circle_membrane")

-- 1. the string
local plain = sm.run{ ends = "walls", mode = 1, basis = "bspline2", mass = "lumped", scheme = "usl" }
local sub = sm.run{ ends = "walls", mode = 1, basis = "bspline2", substeps = 4, scheme = "usl" }
print(string.format("string, usl: plain %+.3f %%, 4 sub-steps %+.3f %%", 100 * plain.err, 100 * sub.err))
assert(math.abs(sub.err) < 0.01, string.format("string, 4 sub-steps: frequency off by %.3f %%", 100 * sub.err))
assert(math.abs(sub.err - plain.err) < 1e-3,
       string.format("string: the sub-steps changed the frequency by %.4f %%", 100 * (sub.err - plain.err)))

-- 2, 3. the circle
local function outside(beyond, _, grazing) return beyond + grazing end
local p0, r, t, E, nu = 1000, 0.5, 0.1, 1e6, 0.3
local function circle(k, scheme, slack)
  local sim = lamina.sim{ domain = {0, 0, 1, 1}, cell = 0.1, dt = 0.5e-4 * (k or 1) * (scheme == "usl" and 0.6 or 1),
                          scheme = scheme, substeps = k,
                          boundary = { left = "symmetry", bottom = "symmetry", right = "fixed", top = "fixed" } }
  local air = lamina.gas{ rho = 1, p = p0, gamma = 1.4, mu = 0.2 }
  local skin = lamina.membrane{ rho = 0.5, E = E, nu = nu, thickness = t, law = "plane_stress" }
  local gas = sim:body{ material = air, ppc = 16, name = "gas", fill = "clipped",
                        region = lamina.disk{ center = {0, 0}, radius = r } }
  local mem = sim:membrane{ material = skin, count = 91, name = "membrane", orient = {0, 0},
                            initial_strain = (not slack) and p0 * r / t * (1 - nu * nu) / E or nil,
                            curve = lamina.arc{ center = {0, 0}, radius = r, from = 0, to = 90 } }
  local E0 = sim:energy().total
  local drift = cm.watch_drift(sim, mem, r)
  sim:run{ t_end = 0.05 }
  local wr, ws = drift()
  local st = cm.laplace_ratio(mem, gas, t)
  local res = { wr = wr, ws = ws, st = st, dE = sim:energy().total / E0 - 1, out = outside(mem:escaped(gas)),
                hash = sim:hash() }
  if slack then
    print(string.format("circle started slack (ringing), %s, substeps %s: energy %+.4f %%", scheme or "musl",
                        tostring(k), 100 * res.dE))
  else
    print(string.format("circle, %s, substeps %s: radius %.4f %%, hoop %.4f %%, sigma t / p r %.5f, "
      .. "energy %+.4f %%, gas out %d", scheme or "musl", tostring(k), 100 * wr, 100 * ws, st, 100 * res.dE,
      res.out))
  end
  return res
end
local c = circle(10, "usl")
assert(c.wr < 0.002, string.format("radius moved %.3f %% (limit 0.2 %%)", 100 * c.wr))
assert(c.ws < 0.01, string.format("hoop stress moved %.3f %% (limit 1 %%)", 100 * c.ws))
assert(math.abs(c.st - 1) < 0.01, string.format("sigma t / p r = %.4f", c.st))
assert(c.out == 0, "gas escaped")

local ring0 = circle(nil, nil, true)
circle(nil, "usl", true)   -- the plain USL step's, printed: how much of the fall is USL's own
for _, k in ipairs{4, 10} do
  local ring = circle(k, "usl", true)
  assert(ring.dE <= math.max(0, ring0.dE),
         string.format("ringing, %d sub-steps (usl): energy %+.4f %% grew beyond the plain step's %+.4f %%", k,
                       100 * ring.dE, 100 * ring0.dE))
end

-- 4. determinism
assert(circle(4, "usl").hash == circle(4, "usl").hash, "two runs with substeps = 4 (usl) differ")
