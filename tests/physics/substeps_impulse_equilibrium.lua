-- Issue 36 item 1: multi-rate stepping's impulse form (lamina.sim{substeps,
-- multirate = "impulse"}) on the gas-filled quarter circle in equilibrium
-- (tests/physics/substeps.lua's: cell 0.1, p = 1000, sigma t = p r at the
-- start), the gas at 10 times the plain step (0.5e-4), to t = 0.05: radius
-- within 0.2 %, hoop within 1 % over the run, sigma t = p r within 1 % at the
-- end, no gas out (what "held" and the plain step hold, substeps.lua).
-- EXPECTED FAILURE (WILL_FAIL in tests/CMakeLists.txt). Measured 2026-12-05:
-- radius 0.215 %, hoop 45.1 %, sigma t / p r 0.703 at the end. The kick gives
-- the nodes the whole step's gas impulse dt f^G at once while the membrane's
-- tension, which balances it, acts over the sub-steps: the membrane is pushed
-- out by about dt^2 f^G / (2 M) each step and pulled back, a strain swing of
-- that over r (dt = 5e-4, f^G / M ~ p / (rho h) = 1e4: 1.25e-3 / 0.5 =
-- 2.5e-3 against the equilibrium strain p r / (t E) = 5e-3, so about half the
-- hoop stress) at the step's rate. The energy does not drift
-- (tests/physics/substeps_impulse.lua); the state at a step's end is a phase
-- of that swing (docs/performance.md "Multi-rate stepping: impulse forms").
local cm = require("circle_membrane")
local p0, r, t, E, nu, k = 1000, 0.5, 0.1, 1e6, 0.3, 10
local sim = lamina.sim{ domain = {0, 0, 1, 1}, cell = 0.1, dt = 0.5e-4 * k, substeps = k, multirate = "impulse",
                        boundary = { left = "symmetry", bottom = "symmetry", right = "fixed", top = "fixed" } }
local air = lamina.gas{ rho = 1, p = p0, gamma = 1.4, mu = 0.2 }
local skin = lamina.membrane{ rho = 0.5, E = E, nu = nu, thickness = t, law = "plane_stress" }
local gas = sim:body{ material = air, ppc = 16, name = "gas", fill = "clipped",
                      region = lamina.disk{ center = {0, 0}, radius = r } }
local mem = sim:membrane{ material = skin, count = 91, name = "membrane", orient = {0, 0},
                          initial_strain = p0 * r / t * (1 - nu * nu) / E,
                          curve = lamina.arc{ center = {0, 0}, radius = r, from = 0, to = 90 } }
local drift = cm.watch_drift(sim, mem, r)
sim:run{ t_end = 0.05 }
local wr, ws = drift()
local st = cm.laplace_ratio(mem, gas, t)
local beyond, _, grazing = mem:escaped(gas)
print(string.format("circle, impulse, 10 sub-steps: radius %.4f %%, hoop %.4f %%, sigma t / p r %.5f, gas out %d",
                    100 * wr, 100 * ws, st, beyond + grazing))
assert(wr < 0.002, string.format("radius moved %.3f %% (limit 0.2 %%)", 100 * wr))
assert(ws < 0.01, string.format("hoop stress moved %.3f %% (limit 1 %%)", 100 * ws))
assert(math.abs(st - 1) < 0.01, string.format("sigma t / p r = %.4f", st))
assert(beyond + grazing == 0, "gas escaped")
