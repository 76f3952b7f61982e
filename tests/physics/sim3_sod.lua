-- Sod's shock tube along z of a 3D tube through the Lua API (issue 34 item
-- 1; [F] §4.1, Fig 6; docs/physics.md V4): the 2D page's set-up
-- (assets/lua/sod.lua: left rho = 1, p = 1, right rho = 0.125, p = 0.1,
-- gamma = 1.4, [F]'s artificial viscosity, dx 0.005, 3 points a cell along
-- the tube, dt 1e-4, t = 0.143, trilinear MUSL) in a tube 2 x 2 cells
-- square between symmetry faces, fixed ends: test_sim3_gas.c's sod_tube
-- set-up (the same points and materials; the engine's run through C gave
-- shock 0.31 cells off, plateau rho -0.84 %, p +0.20 %; this run gives
-- the same shock 0.752114171696, rho 0.263334932024, p 0.303746693203 to
-- the 12 digits compared). Reference: the exact
-- Riemann solution (assets/lua/riemann.lua, through sod.exact); measures
-- sod.measure's on the stations' means over the cross-section (as the C
-- test). Checks: the shock within 2 cells, the right plateau within 5 % in
-- rho and p (tests/physics/sod.lua's tolerances), the tube stays
-- one-dimensional, particles() pressure = (gamma - 1) rho e, and the
-- energy's internal part is the gases' sum m e.
-- Then a gas at rest in a closed box stays at rest (test_sim3_gas.c's
-- at_rest through the API): |v| < 1e-12, |dp| < 1e-11 p, sum m e unchanged
-- to 1e-12.
local sod = require("sod")
local dx, per, across = 0.005, 3, 2
local sim = lamina.sim{ dim = 3, domain = {0, 0, 0, across * dx, across * dx, 1}, cell = dx,
                        dt = 1e-4, basis = "linear", scheme = "musl",
                        boundary = { x0 = "symmetry", x1 = "symmetry", y0 = "symmetry",
                                     y1 = "symmetry", z0 = "fixed", z1 = "fixed" } }
local hi = lamina.gas{ rho = 1, p = 1, gamma = 1.4, av = true }
local lo = lamina.gas{ rho = 0.125, p = 0.1, gamma = 1.4, av = true }
local function box(z0, z1) return lamina.box{ x0 = 0, y0 = 0, z0 = z0, x1 = across * dx,
                                              y1 = across * dx, z1 = z1 } end
local L = sim:body{ material = hi, ppc = {1, 1, per}, region = box(0, 0.5), name = "left" }
local R = sim:body{ material = lo, ppc = {1, 1, per}, region = box(0.5, 1), name = "right" }
assert(#L == 100 * per * across * across and #R == #L, "unexpected counts " .. #L .. " " .. #R)

-- each particle's station along the tube, from where it was seeded
local station = {}
for _, b in ipairs{L, R} do
  local q, s = b:particles(), {}
  for i = 1, q.n do s[i] = math.floor(q.z[i] / (dx / per)) + 1 end
  station[b] = s
end
sim:run{ t_end = 0.143 }

local nst, ncross = 200 * per, across * across
local f = { x = {}, rho = {}, u = {}, p = {}, e = {} }
for i = 1, nst do f.x[i], f.rho[i], f.u[i], f.p[i], f.e[i] = 0, 0, 0, 0, 0 end
local first, spread, eos, me = {}, 0, 0, 0
for _, b in ipairs{L, R} do
  local q, s = b:particles(), station[b]
  for i = 1, q.n do
    local k = s[i]
    f.x[k] = f.x[k] + q.z[i] / ncross
    f.rho[k] = f.rho[k] + q.rho[i] / ncross
    f.u[k] = f.u[k] + q.vz[i] / ncross
    f.p[k] = f.p[k] + q.pressure[i] / ncross
    f.e[k] = f.e[k] + q.e[i] / ncross
    first[k] = first[k] or q.z[i]
    spread = math.max(spread, math.abs(q.z[i] - first[k]))
    eos = math.max(eos, math.abs(q.pressure[i] - (1.4 - 1) * q.rho[i] * q.e[i]))
    assert(q.p[i] == q.pressure[i], "p and pressure differ")
    me = me + q.mass[i] * q.e[i]
  end
end
local r, ex = sod.measure(f, sim.t), sod.exact
local internal = sim:energy().internal
print(string.format("3D Sod along z through the API (%d particles, t = %g): shock at %.4f "
  .. "(exact %.4f, %.2f cells off); plateau rho %.4f (exact %.4f, %+.2f %%), p %.4f (exact "
  .. "%.4f, %+.2f %%) over %d stations; cross-section spread %.2g m; internal %.17g (sum m e "
  .. "%.17g)", sim.n, sim.t, r.shock or -1, r.x_shock,
  math.abs((r.shock or 0) - r.x_shock) / dx, r.rho_plateau, ex.rho_star_right,
  100 * (r.rho_plateau - ex.rho_star_right) / ex.rho_star_right, r.p_plateau, ex.p_star,
  100 * (r.p_plateau - ex.p_star) / ex.p_star, r.n, spread, internal, me))
assert(r.shock and math.abs(r.shock - r.x_shock) <= 2 * dx, "shock not within 2 cells")
assert(r.n >= 5 and math.abs(r.rho_plateau - ex.rho_star_right) / ex.rho_star_right <= 0.05,
       "plateau density off by more than 5 %")
assert(math.abs(r.p_plateau - ex.p_star) / ex.p_star <= 0.05, "plateau pressure off by more than 5 %")
assert(spread < 1e-12, "the tube did not stay one-dimensional: " .. spread)
assert(eos == 0, "particles().pressure is not (gamma - 1) rho e: " .. eos)
assert(math.abs(internal - me) <= 1e-12 * me, "energy().internal is not sum m e")

-- a gas at rest in a closed box (fixed x and y faces, symmetry z), 8
-- points a cell, 200 steps: p = 10 Pa, c = 3.4 m/s, dt c / h = 0.068
for _, basis in ipairs{"linear", "bspline2"} do
  local s = lamina.sim{ dim = 3, domain = {0, 0, 0, 0.4, 0.3, 0.2}, cell = 0.05, dt = 1e-3,
                        basis = basis, boundary = { z0 = "symmetry", z1 = "symmetry" } }
  local air = lamina.gas{ rho = 1.2, p = 10 }
  local b = s:body{ material = air, region = lamina.box{ x0 = 0, y0 = 0, z0 = 0, x1 = 0.4,
                                                         y1 = 0.3, z1 = 0.2 } }
  local e0 = s:energy().internal
  s:step(200)
  local e1 = s:energy().internal
  local q, vmax, dp = b:particles(), 0, 0
  for i = 1, q.n do
    vmax = math.max(vmax, math.abs(q.vx[i]), math.abs(q.vy[i]), math.abs(q.vz[i]))
    dp = math.max(dp, math.abs(q.pressure[i] - 10), math.abs(-q.sxx[i] - 10),
                  math.abs(-q.syy[i] - 10), math.abs(-q.szz[i] - 10))
  end
  print(string.format("gas at rest %s: %d particles, 200 steps: |v| %.2g m/s, |dp| %.2g Pa of "
    .. "10, internal energy %.17g -> %.17g", basis, q.n, vmax, dp, e0, e1))
  assert(q.n == 8 * 8 * 6 * 4, "unexpected count " .. q.n)
  assert(vmax < 1e-12, "the gas at rest moved: " .. vmax)
  assert(dp < 1e-11 * 10, "the pressure at rest changed: " .. dp)
  assert(math.abs(e1 - e0) <= 1e-12 * e0, "the internal energy at rest changed")
end
