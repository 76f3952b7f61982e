-- V6 gas-filled circular membrane ([N] §8, Figs 12-13; docs/physics.md V6):
-- quarter symmetry, radius 0.5, 91 membrane points, E = 1e6, nu = 0.3,
-- rho = 0.5, t = 0.1 (plane stress), initially unstressed; gas gamma = 1.4,
-- p0 = 1000, rho = 1, mu = 0.2, 16 ppc; 10 x 10 cells of 0.1; dt = 0.7e-4
-- (Courant 1.04 on the membrane's plane-stress wave speed: the paper's dt,
-- so courant is raised to 1.05); t_end = 0.05; connectivity normals.
-- The gas pushes the slack membrane out and the system rings for long
-- (period ~0.0035; the mean hoop stress swings between ~0 and twice p r / t).
-- Checks: averaged over [0.0125, 0.05] (about ten periods), the hoop
-- stress is within 5 % of p r / t (averaged p and r); the membrane stays
-- circular (radius at 0 and 90 degrees within 1 %); no gas escapes; total
-- energy stays within 0.1 % (viscous dissipation is small here).
-- every gas particle outside the membrane: membrane:escaped's count beyond a
-- quarter cell plus its skin-grazers (issue 30: the count this file used)
local function outside(beyond, _, grazing) return beyond + grazing end
local sim, gas, mem = require("circle_membrane").setup()
-- the space mean before the first step: the polygon of the 91 points has
-- area 90 (r^2 / 2) sin 1 deg, and the clipped gas (gamma - 1) m e = p0 A
-- over the exact quarter disk pi r^2 / 4 (seed.c; to 1e-5)
local poly = 90 * 0.5 * 0.25 * math.sin(math.rad(1))
assert(math.abs(mem:enclosed_area() - poly) <= 1e-12, "enclosed area of the quarter polygon")
local p_space = gas:pressure(mem)
assert(math.abs(p_space / (1000 * (math.pi / 16) / poly) - 1) <= 5e-5,
       string.format("space-mean pressure at t = 0: %.6f", p_space))
assert(math.abs(gas:pressure("particles") - 1000) <= 1e-9, "particle-mean pressure at t = 0")
local escaped = 0
local rec = sim:record{ every = 1e-4, energy = true, values = {
  p = function() return gas:pressure("particles") end,
  hoop = function() return mem:hoop_stress() end,
  r0 = function() return mem:radius_at(0) end,
  r90 = function() return mem:radius_at(90) end,
  escaped = function() escaped = math.max(escaped, outside(mem:escaped(gas))); return escaped end } }
sim:run{ t_end = 0.05 }

local t0, t1 = 0.0125, 0.05
local p, hoop = rec:mean("p", t0, t1), rec:mean("hoop", t0, t1)
local r0, r90 = rec:mean("r0", t0, t1), rec:mean("r90", t0, t1)
local theory = p * 0.5 * (r0 + r90) / 0.1
local tot = rec:column("total")
local drift = math.abs(tot[#tot] - tot[1]) / tot[1]
print(string.format("V6: mean p %.2f, r(0) %.5f, r(90) %.5f, hoop %.1f vs p r / t %.1f (%+.2f %%); "
  .. "gas outside %d; energy drift %.4f %%", p, r0, r90, hoop, theory,
  100 * (hoop - theory) / theory, escaped, 100 * drift))
assert(math.abs(hoop - theory) / theory <= 0.05, "hoop stress not within 5 % of p r / t")
assert(math.abs(r0 - r90) / r0 <= 0.01, "not circular")
assert(escaped == 0, "gas escaped the membrane")
assert(drift <= 0.001, "energy drift above 0.1 %")
