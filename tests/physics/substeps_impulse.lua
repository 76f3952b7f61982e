-- Issue 36 item 1: multi-rate stepping's impulse form, lamina.sim{substeps = k,
-- multirate = "impulse"} (src/mpm/subcycle.c; docs/performance.md "Multi-rate
-- stepping: impulse forms"). The step's slow (gas) impulse dt f^G is given in
-- the first sub-step (r-RESPA / Verlet-I's kick), the gas's nodal momentum is
-- carried as its consistent re-map and the gas strained by the sub-steps'
-- re-mapped velocities: each sub-step is the plain FLIP-MUSL step with the
-- gas's stress frozen, a symplectic composition, so the energy oscillates
-- (the kick's offset, first order in dt) but does not drift. What it must hold:
-- 1. the walled string (assets/lua/string_modes.lua), mode 1 with 4
--    sub-steps: within 1 % of f_1 = (1 / 2L) sqrt(T / mu) and within 0.1 % of
--    the plain step's (no gas: the sub-steps are the plain steps of dt / k);
-- 2. the gas-filled quarter circle of tests/physics/substeps.lua (cell 0.1,
--    p = 1000) started slack, ringing, 10 sub-steps, to t = 1 (the
--    total energy every 0.01): the energy's trend (least-squares slope times
--    the run's length) within 0.05 % of the start's and within twice the
--    plain MUSL step's, and every sample within 0.25 % (the kick's bounded
--    oscillation); the "held" form, run beside it, must drift by more than
--    1 % (that the check can tell the two apart). Measured 2026-12-05:
--    trend plain -0.0069 %, impulse -0.0060 % (largest 0.185 %, the
--    oscillation), held +5.45 % (+4.55 % at the end);
-- 3. deterministic: the same run twice, the same hash.
-- The same circle in equilibrium is tests/physics/substeps_impulse_equilibrium.lua
-- (an expected failure: the kick rings the loaded membrane).
-- String: plain -0.259 %, impulse -0.259 %.
local sm = require("string_modes")
local cm = require("circle_membrane")

-- 1. the string
local plain = sm.run{ ends = "walls", mode = 1, basis = "bspline2", mass = "lumped" }
local sub = sm.run{ ends = "walls", mode = 1, basis = "bspline2", substeps = 4, multirate = "impulse" }
print(string.format("string: plain %+.3f %%, 4 sub-steps (impulse) %+.3f %%", 100 * plain.err, 100 * sub.err))
assert(math.abs(sub.err) < 0.01, string.format("string, impulse: frequency off by %.3f %%", 100 * sub.err))
assert(math.abs(sub.err - plain.err) < 1e-3,
       string.format("string: the impulse sub-steps changed the frequency by %.4f %%", 100 * (sub.err - plain.err)))

-- 2. the circle
local function outside(beyond, _, grazing) return beyond + grazing end
local p0, r, t, E, nu = 1000, 0.5, 0.1, 1e6, 0.3
local function circle(k, multirate, slack, t_end)   -- (shared with the equilibrium test)
  local sim = lamina.sim{ domain = {0, 0, 1, 1}, cell = 0.1, dt = 0.5e-4 * (k or 1), substeps = k,
                          multirate = multirate,
                          boundary = { left = "symmetry", bottom = "symmetry", right = "fixed", top = "fixed" } }
  local air = lamina.gas{ rho = 1, p = p0, gamma = 1.4, mu = 0.2 }
  local skin = lamina.membrane{ rho = 0.5, E = E, nu = nu, thickness = t, law = "plane_stress" }
  local gas = sim:body{ material = air, ppc = 16, name = "gas", fill = "clipped",
                        region = lamina.disk{ center = {0, 0}, radius = r } }
  local mem = sim:membrane{ material = skin, count = 91, name = "membrane", orient = {0, 0},
                            initial_strain = (not slack) and p0 * r / t * (1 - nu * nu) / E or nil,
                            curve = lamina.arc{ center = {0, 0}, radius = r, from = 0, to = 90 } }
  local E0 = sim:energy().total
  local ts, es = {}, {}
  sim:every(0.01, function(s)
    ts[#ts + 1] = s.t
    es[#es + 1] = s:energy().total / E0 - 1
  end)
  local drift = cm.watch_drift(sim, mem, r)
  sim:run{ t_end = t_end or 0.05 }
  ts[#ts + 1], es[#es + 1] = sim.t, sim:energy().total / E0 - 1
  local wr, ws = drift()
  local trend, worst = cm.energy_trend(ts, es)   -- least-squares slope times the run's length
  local n = #ts
  local res = { wr = wr, ws = ws, st = cm.laplace_ratio(mem, gas, t), out = outside(mem:escaped(gas)),
                trend = trend, worst = worst, dE = es[n], hash = sim:hash() }
  print(string.format("circle%s, substeps %s, %s: radius %.4f %%, hoop %.4f %%, sigma t / p r %.5f, energy: end %+.4f %%, "
    .. "trend %+.4f %%, largest %.4f %%, gas out %d", slack and " (slack, ringing)" or "", tostring(k),
    tostring(multirate), 100 * wr, 100 * ws, res.st, 100 * res.dE, 100 * res.trend, 100 * worst, res.out))
  return res
end
local plain_ring = circle(nil, nil, true, 1)   -- the plain MUSL step's
local held = circle(10, "held", true, 1)
local imp = circle(10, "impulse", true, 1)
assert(held.trend > 0.01, string.format("held: trend %+.4f %%, expected its drift above 1 %%", 100 * held.trend))
assert(math.abs(imp.trend) < 5e-4, string.format("impulse: energy trend %+.4f %% over t = 1 (limit 0.05 %%)",
                                                 100 * imp.trend))
assert(math.abs(imp.trend) <= 2 * math.abs(plain_ring.trend),
       string.format("impulse: energy trend %+.4f %% against the plain step's %+.4f %% (limit twice that)",
                     100 * imp.trend, 100 * plain_ring.trend))
assert(imp.worst < 2.5e-3, string.format("impulse: energy off by %.4f %% (limit 0.25 %%)", 100 * imp.worst))

-- 3. determinism
assert(circle(4, "impulse").hash == circle(4, "impulse").hash, "two runs with multirate = \"impulse\" differ")
