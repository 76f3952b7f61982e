-- courant_sheet_mass.lua - the largest stable dt c / h of the trampoline's
-- sheet alone under gravity (docs/robustness.md "The stable step": pinned
-- at both ends, cell 0.05, c = sqrt(E / rho) = 100, segment forces), by
-- points a cell, on the lumped mass and with the consistent-mass correction
-- (lamina.sim{mass = "corrected" | "membrane"}; issue 30 item 2: the
-- Courant factor the correction really needs on a membrane).
--
-- Stable: 0.5 s without an error, and the total energy never more than
-- 10 % of the sheet's initial strain energy away from its start (a
-- growing mode passes that within a few dozen steps; the sag itself moves
-- it by < 1 %). Bisection to 0.005 between 0.2 and 2.5, the check's own
-- refusal lifted (courant = 100).
--   lamina run scripts/measure/courant_sheet_mass.lua [--set mass=membrane]
--     [--set ppc="1 2 3 4 8"] [--set t_end=0.5] [--set basis=linear]
local mass = lamina.param("mass", "lumped")
local ppcs = lamina.param("ppc", "1 2 3 4 8")
local t_end = lamina.param("t_end", 0.5)
local basis = lamina.param("basis", "bspline2")
local h, E, rho, t, eps0 = 0.05, 1e7, 1000, 0.005, 0.01
local c = math.sqrt(E / rho)

local function stable(cn, ppc)
  local sim = lamina.sim{ domain = {0, 0, 2, 1.5}, cell = h, dt = cn * h / c, courant = 100,
                          gravity = {0, -9.81}, mass = mass, basis = basis,
                          boundary = {left = "free", right = "free", bottom = "free", top = "free"} }
  local mat = lamina.membrane{ rho = rho, E = E, nu = 0, thickness = t, law = "uniaxial" }
  local sheet = sim:membrane{ material = mat, curve = lamina.segment{from = {0.2, 0.5}, to = {1.8, 0.5}},
                              spacing = h / ppc, initial_strain = eps0 }
  sheet:pin{ points = {1} }
  sheet:pin{ points = {#sheet} }
  local e0 = sim:energy().total
  local w0 = 0.5 * E * t * eps0 ^ 2 * 1.6
  local ok = true
  sim:every(2e-3, function(s)
    if math.abs(s:energy().total - e0) > 0.1 * w0 then ok = false; error("grows") end
  end)
  local fine = pcall(function() sim:run{ t_end = t_end } end)
  return fine and ok
end

for ppc in ppcs:gmatch("%S+") do
  ppc = tonumber(ppc)
  local lo, hi = 0.2, 2.5
  assert(stable(lo, ppc), "not stable even at " .. lo)
  while hi - lo > 0.005 do
    local mid = 0.5 * (lo + hi)
    if stable(mid, ppc) then lo = mid else hi = mid end
  end
  print(string.format("sheet, %d points a cell, %s, mass %s: largest stable dt c / h %.3f", ppc, basis, mass, lo))
end
