-- Issue 36 item 1: multi-rate stepping (lamina.sim{substeps}, src/mpm/subcycle.c).
--
-- 1. A membrane alone: the string of assets/lua/string_modes.lua on fixed
--    walls (segment forces, the quadratic B-spline), mode 1, stepping 4 x
--    its 0.4 h / c with 4 sub-steps against the plain step of 0.4 h / c:
--    both within 1 % of f_1 = (1 / 2L) sqrt(T / mu), and within 0.1 % of
--    each other (without gas the sub-steps are the plain steps of dt / k);
--    the total energy within 1 % of the largest kinetic energy in both.
-- 2. The gas-filled quarter circle of tests/physics/circle_equilibrium.lua
--    started in equilibrium (sigma t = p r, plane stress, cell 0.1,
--    p = 1000, c_gas = 37, c_membrane = 1482): with 4 and 10 sub-steps
--    (the gas at dt = 2e-4 and 5e-4, 4 and 10 times the plain 0.5e-4) the
--    radius stays within 0.2 % and the hoop stress within 1 % over 0.05 s,
--    sigma t = p r within 1 % at the end, no gas out, and the total energy
--    (no damping here) changes by no more than 1e-5 of itself, as the plain
--    step's.
-- 3. substeps = 1 is the plain step, USL and MUSL (the groups' split only
--    re-adds the same nodal sums): the same radius and hoop to 1e-9.
-- 4. Deterministic: the same run twice, the same state hash.
-- 5. substeps = "auto" picks the fewest sub-steps within the Courant limit.
-- Measured (2026-12-05): string -0.26 % plain, -0.26 % with 4 sub-steps;
-- circle radius 0.0119 / 0.0119 / 0.0120 %, hoop 0.056 / 0.058 / 0.061 %
-- (plain / 4 / 10 sub-steps), energy change 2.1e-9 / 2.9e-7 / 7.9e-7 of
-- itself (the gas steps 4 and 10 times longer: its time error grows; the
-- moving case, tests/physics/substeps_energy.lua, is an expected failure).
local sm = require("string_modes")
local cm = require("circle_membrane")

-- 1. the string (the plain step on mass = "lumped", named: the default is
-- "membrane" for segment membranes without substeps, and sub-stepping is
-- lumped only, l_sim.c)
local plain = sm.run{ ends = "walls", mode = 1, basis = "bspline2", mass = "lumped" }
local sub = sm.run{ ends = "walls", mode = 1, basis = "bspline2", substeps = 4 }
for name, r in pairs{ plain = plain, substeps = sub } do
  assert(math.abs(r.err) < 0.01, string.format("string, %s: frequency off by %.3f %%", name, 100 * r.err))
  assert(r.de < 0.01, string.format("string, %s: energy changed by %.3f %% of the largest KE", name,
                                    100 * r.de))
end
assert(math.abs(sub.err - plain.err) < 1e-3,
       string.format("string: the sub-steps changed the frequency by %.4f %%", 100 * (sub.err - plain.err)))

-- 2. the circle in equilibrium
local function outside(beyond, _, grazing) return beyond + grazing end
local p0, r, t, E, nu = 1000, 0.5, 0.1, 1e6, 0.3
local function circle(k, scheme, dt0)
  dt0 = dt0 or 0.5e-4
  local sim = lamina.sim{ domain = {0, 0, 1, 1}, cell = 0.1, dt = dt0 * (k or 1), scheme = scheme,
                          substeps = k, mass = "lumped",   -- the plain step as the sub-steps' (1.)
                          boundary = { left = "symmetry", bottom = "symmetry",
                                                     right = "fixed", top = "fixed" } }
  local air = lamina.gas{ rho = 1, p = p0, gamma = 1.4, mu = 0.2 }
  local skin = lamina.membrane{ rho = 0.5, E = E, nu = nu, thickness = t, law = "plane_stress" }
  local gas = sim:body{ material = air, ppc = 16, name = "gas", fill = "clipped",
                        region = lamina.disk{ center = {0, 0}, radius = r } }
  local eps = p0 * r / t * (1 - nu * nu) / E
  local mem = sim:membrane{ material = skin, count = 91, name = "membrane", orient = {0, 0},
                            initial_strain = eps,
                            curve = lamina.arc{ center = {0, 0}, radius = r, from = 0, to = 90 } }
  assert(sim.substeps == (k or 1), "sim.substeps reads " .. sim.substeps)
  local E0 = sim:energy().total
  local drift = cm.watch_drift(sim, mem, r)
  sim:run{ t_end = 0.05 }
  local wr, ws = drift()
  local st = cm.laplace_ratio(mem, gas, t)
  local res = { wr = wr, ws = ws, st = st, dE = math.abs(sim:energy().total / E0 - 1),
                out = outside(mem:escaped(gas)), hash = sim:hash(), r = mem:radius_at(45),
                hoop = mem:hoop_stress() }
  print(string.format("circle, %s, substeps %s: radius %.4f %%, hoop %.4f %%, sigma t / p r %.5f, "
    .. "energy change %.2e, gas out %d", scheme or "musl", tostring(k), 100 * wr, 100 * ws, st,
    res.dE, res.out))
  return res
end
local c0 = circle(nil)
for _, k in ipairs{4, 10} do
  local c = circle(k)
  assert(c.wr < 0.002, string.format("substeps %d: radius moved %.3f %% (limit 0.2 %%)", k, 100 * c.wr))
  assert(c.ws < 0.01, string.format("substeps %d: hoop stress moved %.3f %% (limit 1 %%)", k, 100 * c.ws))
  assert(math.abs(c.st - 1) < 0.01, string.format("substeps %d: sigma t / p r = %.4f", k, c.st))
  assert(c.out == 0, "gas escaped")
  assert(c.dE <= math.max(1e-5, 2 * c0.dE),
         string.format("substeps %d: energy changed by %.2e (plain %.2e)", k, c.dE, c0.dE))
end

-- 3. one sub-step is the plain step, USL and MUSL
for _, sc in ipairs{ {"usl", 3e-5}, {"musl", 0.5e-4} } do
  local u0, u1 = circle(nil, sc[1], sc[2]), circle(1, sc[1], sc[2])
  assert(math.abs(u1.r - u0.r) < 1e-9 and math.abs(u1.hoop / u0.hoop - 1) < 1e-9,
         string.format("substeps = 1 (%s): radius %.12g vs %.12g, hoop %.12g vs %.12g", sc[1], u1.r,
                       u0.r, u1.hoop, u0.hoop))
end

-- 4. determinism
assert(circle(4).hash == circle(4).hash, "two runs with substeps = 4 differ")

-- 5. "auto": the fewest sub-steps within the Courant limit (1): the
-- segment membrane's c counts as sqrt(E / ((1 - nu^2) rho)) / 0.75
-- (docs/api.md), so at dt = 5e-4 on cell 0.1 k = ceil(5e-4 c / 0.1)
do
  local c = math.sqrt(E / ((1 - nu * nu) * 0.5)) / 0.75
  local sim = lamina.sim{ domain = {0, 0, 1, 1}, cell = 0.1, dt = 5e-4, substeps = "auto" }
  local skin = lamina.membrane{ rho = 0.5, E = E, nu = nu, thickness = t, law = "plane_stress" }
  sim:membrane{ material = skin, count = 91,
                curve = lamina.arc{ center = {0.5, 0.5}, radius = 0.3, from = 0, to = 90 } }
  local want = math.ceil(5e-4 * c / 0.1)
  assert(sim.substeps == want, string.format("auto: %d sub-steps, want %d", sim.substeps, want))
  sim:run{ t_end = 2e-3 }   -- passes the Courant check
  print(string.format("auto: %d sub-steps at dt = 5e-4 (membrane c = %.0f)", sim.substeps, c))
end
