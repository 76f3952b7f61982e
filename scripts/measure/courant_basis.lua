-- courant_basis.lua - the largest stable Courant number dt c / h of each
-- basis (lamina.sim{basis}) on a 1D elastic bar, MUSL (docs/decisions.md
-- "Shape functions"; lm_basis_courant_factor in src/mpm/shape.c).
--
-- The bar of tests/physics/bar_vibration.lua: length 1, fixed at x = 0,
-- free at x = 1, one cell high between symmetry walls, plane stress with
-- nu = 0 (c = sqrt(E / rho)), 2 x 2 points per cell, started in its first
-- mode. A Courant number is stable when `steps` steps run without failure
-- and the total energy, looked at every 500 steps, never exceeds 1.1 times
-- its start (the instability grows from round-off, exponentially: a run
-- near the edge either blows up or stays put; the energy of a stable run
-- wanders by a few per cent with the phase at which it is sampled, and
-- decays slowly, so only growth counts). Bisection to 0.005 between 0.2
-- and 4.
--   lamina run scripts/measure/courant_basis.lua [--set cells=40 --set steps=20000 --set ppc=2]
--     [--set mass=corrected] [--set bases=bspline2] (lamina.sim{mass};
--     bases: one basis, or "all")
local cells = lamina.param("cells", 40)
local steps = lamina.param("steps", 20000)
local ppc = lamina.param("ppc", 2)
local scheme = lamina.param("scheme", "musl")
local mass = lamina.param("mass", "lumped")
local bases = lamina.param("bases", "all")
bases = bases == "all" and { "linear", "gimp", "bspline2" } or { bases }
local L, E, rho, v0 = 1.0, 100, 1, 0.01
local h = L / cells
local c = math.sqrt(E / rho)

local function stable(basis, cn)
  local sim = lamina.sim{ domain = {0, 0, 1.25, h}, cell = h, dt = cn * h / c, courant = 100,
                          basis = basis, scheme = scheme, mass = mass,
                          boundary = { left = "fixed", right = "free",
                                       bottom = "symmetry", top = "symmetry" } }
  local steel = lamina.elastic{ rho = rho, E = E, nu = 0, plane = "stress" }
  sim:body{ material = steel, ppc = {ppc, ppc},
            region = lamina.rect{ x0 = 0, y0 = 0, x1 = L, y1 = h },
            velocity = function(x, y) return v0 * math.sin(math.pi * x / (2 * L)), 0 end }
  local e0 = sim:energy().total
  for _ = 1, steps // 500 do
    if not pcall(function() sim:step(500) end) then return false end
    local e = sim:energy().total
    if not (e <= 1.1 * e0) then return false end
  end
  return true
end

print(string.format("1D bar, %d cells, %d x %d points per cell, %s, mass %s, %d steps per trial",
                    cells, ppc, ppc, scheme, mass, steps))
print("| basis | largest stable dt c / h | relative to linear |")
print("|---|---:|---:|")
local lin
for _, basis in ipairs(bases) do
  local lo, hi = 0.2, 4
  assert(stable(basis, lo), basis .. ": not stable even at " .. lo)
  while hi - lo > 0.005 do
    local mid = 0.5 * (lo + hi)
    if stable(basis, mid) then lo = mid else hi = mid end
  end
  lin = lin or lo
  print(string.format("| %s | %.3f | %.3f |", basis, lo, lo / lin))
end
