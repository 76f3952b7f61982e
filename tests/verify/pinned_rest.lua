-- Verification case (issue 30 item 1): the pinned membrane at rest. A string
-- of length 1 laid straight at 15 degrees to the grid (uniaxial, E = 5e4,
-- thickness 0.01, rho = 100), stretched by eps0 = 0.01 (tension
-- T = E eps0 t = 5), its two end points held by body:pin away from the walls,
-- no gravity, for t = 0.5 (about 11 of its longitudinal periods).
-- Exact: a uniformly stretched straight string between fixed points is in
-- equilibrium; nothing moves and the tension stays T. Measured: the largest
-- distance any point moved from its start at any sample (exact 0; error in
-- per cent of a cell) and the mean tension (membrane:hoop_stress() x t) at
-- the end against T. Resolution: level 1, 2 = cell 1/16, 1/32; points h/2
-- apart.
-- verify: membrane
local V = require("lib.vcase")
local E, rho, t, eps0 = 5e4, 100, 0.01, 0.01
local h = 1 / (8 * 2 ^ V.level)
local th = math.rad(15)
local sim = V.sim{ domain = {0, 0, 1.5, 1}, cell = h, dt = 0.4 * h / (math.sqrt(E / rho) / 0.75) }
local wire = lamina.membrane{ rho = rho, E = E, nu = 0, thickness = t, law = "uniaxial" }
local count = math.floor(2 / h + 0.5) + 1
local s = V.membrane(sim, { material = wire, count = count, initial_strain = eps0, name = "string",
                            curve = lamina.segment{ from = {0.25, 0.3}, to = {0.25 + math.cos(th), 0.3 + math.sin(th)} } })
s:pin{ points = {1} }
s:pin{ points = {count} }
local p0 = s:particles()
local moved = 0
sim:every(0.005, function()
  local q = s:particles()
  for i = 1, q.n do moved = math.max(moved, math.sqrt((q.x[i] - p0.x[i]) ^ 2 + (q.y[i] - p0.y[i]) ^ 2)) end
end)
sim:run{ t_end = 0.5 }
V.result{ quantity = "max_displacement", value = moved, exact = 0, scale = h, h = h }
V.result{ quantity = "tension", value = s:hoop_stress() * t, exact = E * eps0 * t, h = h }
