-- Verification case (issue 30 item 1): the speed of sound in the gas. A gas
-- column of length L = 1 between fixed walls, one cell tall between
-- symmetry walls, rho = 1, p = 1, gamma = 1.4, inviscid, 4 points a cell
-- ({2, 2}), started in its first standing mode v = v0 sin(pi x / L) with
-- v0 = 1e-4 c (linear acoustics).
-- Exact (linear acoustics, Landau & Lifshitz, Fluid Mechanics §64):
-- c = sqrt(gamma p / rho) = 1.18322; the mode sin(pi x / L) cos(omega t)
-- with omega = pi c / L, period 2 L / c = 1.69031. The mean velocity of the
-- left half follows cos(omega t). Measured: the period from its upward zero
-- crossings over 4 periods. Resolution: level 1, 2, 3 = 10, 20, 40 cells.
local V = require("lib.vcase")
local L, rho, p, g = 1.0, 1, 1, 1.4
local c = math.sqrt(g * p / rho)
local v0 = 1e-4 * c
local h = L / (5 * 2 ^ V.level)
local P = 2 * L / c
local sim = V.sim{ domain = {0, 0, L, h}, cell = h, dt = 0.2 * h / c,
                   boundary = { left = "fixed", right = "fixed", bottom = "symmetry", top = "symmetry" } }
local air = lamina.gas{ rho = rho, p = p, gamma = g }
local gas = sim:body{ material = air, ppc = 4, region = lamina.rect{ x0 = 0, y0 = 0, x1 = L, y1 = h },
                      velocity = function(x) return v0 * math.sin(math.pi * x / L), 0 end }
local rec = sim:record{ every = P / 100, values = { v = function()
  local q = gas:particles()
  local mv, m = 0, 0
  for i = 1, q.n do
    if q.x[i] < 0.5 * L then mv, m = mv + q.mass[i] * q.vx[i], m + q.mass[i] end
  end
  return mv / m
end } }
sim:run{ t_end = 4.05 * P }
local period = V.period(rec:column("t"), rec:column("v"), 0)
V.result{ quantity = "period", value = period, exact = P, h = h }
