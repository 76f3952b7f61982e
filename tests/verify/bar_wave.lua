-- Verification case (issue 30 item 1): the elastic bar's wave speed. A bar
-- of length L = 1 fixed at x = 0 (fixed wall), free at x = L, one cell tall
-- between symmetry walls, E = 100, rho = 1, nu = 0 (plane stress): a 1D bar,
-- c = sqrt(E / rho) = 10. Started in its first mode v = v0 sin(pi x / 2L).
-- Exact (the wave equation u_tt = c^2 u_xx with u(0) = 0, u_x(L) = 0; Graff,
-- Wave Motion in Elastic Solids §2.1): mode 1 is sin(pi x / 2L) cos(omega t),
-- omega = pi c / 2L, period 4 L / c = 0.4; the bar's mean velocity follows
-- cos(omega t). Measured: the period from its upward zero crossings over 3
-- periods. (tests/physics/bar_vibration.lua is the same bar on the linear
-- basis.) Resolution: level 1, 2, 3 = 10, 20, 40 cells along the bar, 2 x 2
-- points a cell.
local V = require("lib.vcase")
local L, E, rho, v0 = 1.0, 100, 1, 0.01
local h = L / (5 * 2 ^ V.level)
local c = math.sqrt(E / rho)
local P = 4 * L / c
local sim = V.sim{ domain = {0, 0, 1.25, h}, cell = h, dt = 0.2 * h / c,
                   boundary = { left = "fixed", right = "free", bottom = "symmetry", top = "symmetry" } }
local steel = lamina.elastic{ rho = rho, E = E, nu = 0, plane = "stress" }
local bar = sim:body{ material = steel, ppc = 4, region = lamina.rect{ x0 = 0, y0 = 0, x1 = L, y1 = h },
                      velocity = function(x) return v0 * math.sin(math.pi * x / (2 * L)), 0 end }
local rec = sim:record{ every = sim.dt, values = { v = function() return (bar:velocity()) end } }
sim:run{ t_end = 3.05 * P }
local period = V.period(rec:column("t"), rec:column("v"), 0)
V.result{ quantity = "period", value = period, exact = P, h = h }
