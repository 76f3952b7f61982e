-- courant_string.lua - the largest stable dt c / h of a taut string with
-- segment forces (sim:membrane{force = "segment"}) on fixed walls, lumped
-- against corrected mass (lamina.sim{mass}; docs/robustness.md "Corrected
-- mass", LM_SEGMENT_COURANT and LM_CORRECTED_COURANT in src/mpm/include/mpm.h).
--
-- The string of tests/verify/lib/string_modes.lua (E 5e4, rho 100,
-- t 0.01, eps0 0.01, points h/2 apart, mode 1 of amplitude 2e-4), c =
-- sqrt(E / rho) the longitudinal speed the check uses. Stable: `steps`
-- steps without failure and the total energy, every 500 steps, never above
-- 1.1 times its start. Bisection to 0.005 between 0.1 and 3.
--   lamina run scripts/measure/courant_string.lua [--set cells=32 --set steps=10000]
--     [--set basis=bspline2] [--set mass=lumped|corrected] [--set scheme=musl]
local cells = lamina.param("cells", 32)
local steps = lamina.param("steps", 10000)
local basis = lamina.param("basis", "bspline2")
local mass = lamina.param("mass", "lumped")
local scheme = lamina.param("scheme", "musl")
local L, E, rho, t, eps0 = 1, 5e4, 100, 0.01, 0.01
local h = L / cells
local c = math.sqrt(E / rho)

local function stable(cn)
  local sim = lamina.sim{ domain = {0, 0, L, 0.5}, cell = h, dt = cn * h / c, courant = 100,
                          basis = basis, scheme = scheme, mass = mass, boundary = "fixed" }
  local wire = lamina.membrane{ rho = rho, E = E, nu = 0, thickness = t, law = "uniaxial" }
  sim:membrane{ material = wire, count = 2 * cells + 1, initial_strain = eps0, force = "segment",
                curve = function(u) return L * u, 0.25 + 2e-4 * math.sin(math.pi * u) end }
  local e0 = sim:energy().total
  for _ = 1, steps // 500 do
    if not pcall(function() sim:step(500) end) then return false end
    local e = sim:energy().total
    if not (e <= 1.1 * e0) then return false end
  end
  return true
end

local lo, hi = 0.1, 3
assert(stable(lo), "not stable even at " .. lo)
while hi - lo > 0.005 do
  local mid = 0.5 * (lo + hi)
  if stable(mid) then lo = mid else hi = mid end
end
print(string.format("string, %d cells, %s, %s, mass %s: largest stable dt c / h %.3f",
                    cells, basis, scheme, mass, lo))
