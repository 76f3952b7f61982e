-- Issue 13 item 2(b): the gas-filled circular membrane of the normals paper
-- (V6: quarter model, radius 0.5, 91 points, E 1e6, nu 0.3, t 0.1, plane
-- stress; gas p 1000, gamma 1.4, mu 0.2, 16 ppc, cell 0.1) started in
-- equilibrium instead of slack: the membrane laid on the circle with the
-- strain that gives sigma t = p r (p the mean over the enclosed space).
-- Exact answer: nothing moves. It must stay there for 0.05 s (~14 of its
-- ringing periods): radius (at 0, 45 and 90 degrees) within 0.2 % and
-- hoop stress within 1 % at every sample (every 1e-3), with the tension
-- along segments. The papers' point quadrature is run too and its figures
-- printed (measured: radius 0.39 %, hoop 5.1 %: it does not hold). With
-- the quadratic B-spline (lamina.sim{basis = "bspline2"}) and segments it
-- holds too (0.013 %, 0.05 %); GIMP with segments just misses (printed).
-- The first run names neither basis nor force: lamina's defaults (the
-- quadratic B-spline and segments, issue 13 items 1-2) must hold it.
-- every gas particle outside the membrane: membrane:escaped's count beyond a
-- quarter cell plus its skin-grazers (issue 30: the count this file used)
local cm = require("circle_membrane")
local function outside(beyond, _, grazing) return beyond + grazing end
local p0, r, t, E, nu = 1000, 0.5, 0.1, 1e6, 0.3

local function run(force, basis)
  local sim = lamina.sim{ domain = {0, 0, 1, 1}, cell = 0.1, dt = 0.5e-4, basis = basis,
                          boundary = { left = "symmetry", bottom = "symmetry",
                                       right = "fixed", top = "fixed" } }
  local air = lamina.gas{ rho = 1, p = p0, gamma = 1.4, mu = 0.2 }
  local skin = lamina.membrane{ rho = 0.5, E = E, nu = nu, thickness = t, law = "plane_stress" }
  local gas = sim:body{ material = air, ppc = 16, name = "gas", fill = "clipped",
                        region = lamina.disk{ center = {0, 0}, radius = r } }
  local eps = p0 * r / t * (1 - nu * nu) / E        -- sigma = E eps / (1 - nu^2)
  local mem = sim:membrane{ material = skin, count = 91, name = "membrane", force = force,
                            orient = {0, 0}, initial_strain = eps,
                            curve = lamina.arc{ center = {0, 0}, radius = r, from = 0, to = 90 } }
  local p_start, s_start = gas:pressure(mem), mem:hoop_stress()
  -- the start is the equilibrium: sigma t = p r to the seeding's accuracy
  assert(math.abs(s_start * t / (p_start * r) - 1) < 1e-4,
         string.format("start hoop %.4f vs p r / t %.4f", s_start, p_start * r / t))
  local drift = cm.watch_drift(sim, mem, r)
  sim:run{ t_end = 0.05 }
  local wr, ws = drift()
  assert(basis or (sim.basis == "bspline2" and mem.force == "segment"), "the defaults changed")
  print(string.format("%-8s %-7s: radius change max %.3f %%, hoop stress change max %.3f %%, gas out %d",
                      basis or "default", force or "", 100 * wr, 100 * ws, outside(mem:escaped(gas))))
  return wr, ws, outside(mem:escaped(gas))
end

for _, basis in ipairs{false, "linear"} do
  local wr, ws, out = run(basis and "segment" or nil, basis or nil)
  local name = basis or "default"
  assert(wr < 0.002, string.format("%s: radius moved %.3f %% (limit 0.2 %%)", name, 100 * wr))
  assert(ws < 0.01, string.format("%s: hoop stress moved %.3f %% (limit 1 %%)", name, 100 * ws))
  assert(out == 0, "gas escaped")
end
-- measured, not asserted (docs/robustness.md): point quadrature (linear:
-- radius 0.39 %, hoop 5.1 %), and GIMP even with segments (radius 0.22 %,
-- hoop 1.5 %: just outside the limits)
run("point", "linear")
run("segment", "gimp")
