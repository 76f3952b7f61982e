-- spring_mass.lua - [M] §3.1.1's kind of spring-mass (the issue 30 numbers):
-- a vertical string of length L = 0.4, A = 0.1 (thickness), E = 1e6,
-- rho = 0.1, nu = 0 (uniaxial), hanging from the top wall (its first point
-- on the fixed wall y = 2), the last point a heavy mass m = 5, g = 100,
-- released from rest at the unstretched length: k = AE/L = 2.5e5.
--
-- Exact. Static deflection: the membrane law is sigma = E ln(l / L)
-- (docs/api.md, lamina.membrane; the strain is logarithmic), so the mass
-- hangs at E A ln(1 + d / L) = m g, d = L (exp(m g / EA) - 1) = 2.00501e-3
-- (m g / k = 2e-3 to first order). Period: small oscillations about that
-- state have the stiffness dT/dl = EA / (L + d) = k exp(-mg/EA), and the
-- string's own mass m_s = rho A L = 4e-3 adds m_s / 3 (Rayleigh's quotient
-- with the static shape of the string, Timoshenko, Vibration Problems in
-- Engineering §1.8; the exact root of beta tan beta = m_s / m differs by
-- O((m_s/m)^2) = 6e-7): P = 2 pi sqrt((m + m_s/3) / (k exp(-mg/EA))) =
-- 0.028173. The swing (amplitude d about d) changes the stiffness by
-- +-0.5 %, which shifts the period by O(1e-5).
-- Measured over 5 periods: the period from the upward crossings of the
-- mass's height through its mean, and the mean deflection over whole periods.
-- Resolution: level 1, 2 = cell 0.1, 0.05; `ppc` points a cell along the
-- string (1: points a cell apart, 3: a third of a cell).
local V = require("lib.vcase")
local M = {}

function M.run(ppc)
  local L, A, E, rho, m, g = 0.4, 0.1, 1e6, 0.1, 5, 100
  local h = 0.2 / 2 ^ V.level
  local k = A * E / L
  local ms = rho * A * L
  local d = L * (math.exp(m * g / (E * A)) - 1)
  local P = 2 * math.pi * math.sqrt((m + ms / 3) / (k * math.exp(-m * g / (E * A))))
  local c = math.sqrt(E / rho) / 0.75
  local sim = V.sim{ domain = {0, 0, 0.2, 2.0}, cell = h, dt = 0.4 * h / c, gravity = {0, -g},
                     boundary = { left = "symmetry", right = "symmetry", top = "fixed", bottom = "fixed" } }
  local wire = lamina.membrane{ rho = rho, E = E, nu = 0, thickness = A, law = "uniaxial" }
  local count = math.floor(ppc * L / h + 0.5) + 1
  local s = V.membrane(sim, { material = wire, count = count, end_mass = m, name = "spring",
                              curve = lamina.segment{ from = {0.1, 2.0}, to = {0.1, 2.0 - L} } })
  local rec = sim:record{ every = P / 200, points = { mass = {s, -1} } }
  sim:run{ t_end = 5.05 * P }
  local t, y = rec:column("t"), rec:column("mass_y")
  local period, up = V.period(t, y, 2.0 - L - d)
  local mean = (2.0 - L) - rec:mean("mass_y", up[1], up[#up])
  V.result{ quantity = "period", value = period, exact = P, h = h }
  V.result{ quantity = "static_deflection", value = mean, exact = d, h = h }
end

return M
