-- title: Pendulum problem set-up: a string and mass hung from a wall by a ball-and-socket joint
-- source: York, Sulsky & Schreyer 1999 (membranes), §3.1.2, Fig 7; York's dissertation §5.7, Fig 30
-- look: the string of length L hangs from a frictionless joint on the wall,
--   inclined theta_0 from the vertical, the mass m at its end, gravity g
--   downwards, the x-y axes; the table beside it gives [M] Table I / [T]
--   Table 1's values. Drawn to scale.
-- checks: the set-up membrane_pendulum seeds from these values, measured on
--   its material points as [M] §3.1.2 defines theta (the line joining the first
--   and last points): theta_0 = 19.8 deg, L = 0.73 and the end point's mass 3.3
--   (Table I)
-- thumb: sketch_pendulum.png
local sk = require("sketch")
local out = lamina.param("out", "out/sketch_pendulum")

-- [M] Table I / [T] Table 1 (rho and t as [T]; membrane_pendulum's header says why)
local L, m, g, th0, E, rho, nu, t = 0.73, 3.3, 20, 19.8, 1e6, 0.1, 0, 0.1
local px, py = 0.6, 1.0   -- membrane_pendulum's pivot

-- The set-up as membrane_pendulum seeds it (its 40-point string, cell 0.1)
local sim = lamina.sim{ basis = "linear", domain = {0, 0, 1.2, 1.0}, cell = 0.1, dt = 1e-5,
                        gravity = {0, -g} }
local mat = lamina.membrane{ rho = rho, E = E, nu = nu, thickness = t, one_way = true }
local str = sim:membrane{ material = mat, count = 40, end_mass = m, name = "string",
  curve = lamina.segment{ from = {px, py},
                          to = {px + L * math.sin(math.rad(th0)), py - L * math.cos(math.rad(th0))} } }
local p = str:particles()
local n = #p.x
local dx, dy = p.x[n] - p.x[1], p.y[n] - p.y[1]
local theta = math.deg(math.atan(dx, -dy))
local length = math.sqrt(dx * dx + dy * dy)
local mass = p.mass[n]

local fig = lamina.figure{ width = 900, height = 560, panels = {1, 1},
  title = "[M] Fig 7 / [T] Fig 30: pendulum problem set-up" }
fig:panel{ index = 1, window = {-0.55, -0.95, 1.05, 0.12},
           caption = string.format("seeded by lamina (membrane_pendulum): theta_0 %.4f deg, L %.4f, m %.3f",
                                   theta, length, mass) }
-- the wall (a ceiling) and the ball-and-socket joint at the origin
sk.wall(fig, {-0.25, 0}, {0.25, 0}, { side = 1, hatch = 0.05, strokes = 12 })
sk.circle(fig, 0, 0, 0.015)
local ex, ey = L * math.sin(math.rad(th0)), -L * math.cos(math.rad(th0))
-- the vertical and the string
fig:polyline{ points = {{0, 0}, {0, -0.8}}, colour = "grey", dashed = true }
fig:polyline{ points = {{0, 0}, {ex, ey}}, colour = "black", width = 2.5 }
sk.circle(fig, 0, 0, 0.22, { from = -90, to = -90 + th0, width = 1 })
fig:text{ text = "theta_0", at = {0.04, -0.28} }
-- the mass
local r = 0.035
sk.circle(fig, ex, ey, r, { width = 2 })
fig:text{ text = "m", at = {ex + 0.05, ey - 0.01} }
-- the string's length and properties
fig:text{ text = "L;  rho, E, nu, t", at = {0.5 * ex + 0.04, 0.5 * ey} }
-- gravity
sk.arrow(fig, {-0.3, -0.35}, {-0.3, -0.55}, "g")
-- axes
sk.arrow(fig, {-0.5, -0.85}, {-0.35, -0.85}, "x")
sk.arrow(fig, {-0.5, -0.85}, {-0.5, -0.7}, "y")
-- [M] Table I / [T] Table 1
local rows = { {"L", "0.73"}, {"m", "3.3"}, {"g", "20.0"}, {"theta_0", "19.8 deg"},
               {"E", "1e6"}, {"rho", "0.1 ([M]: 1.0)"}, {"nu", "0.0"}, {"t", "0.1 ([M]: 0.01)"} }
fig:text{ text = "[T] Table 1 ([M] Table I)", at = {0.45, -0.05} }
for i, row in ipairs(rows) do
  fig:text{ text = row[1], at = {0.5, -0.05 - 0.09 * i} }
  fig:text{ text = row[2], at = {0.7, -0.05 - 0.09 * i} }
end
fig:write(out .. "/sketch_pendulum.png")

print(string.format("seeded: theta_0 %.6f deg, L %.6f, end mass %.6f", theta, length, mass))
lamina.report{
  theta_0 = { theta, paper = th0, tol = 1e-6, unit = "deg ([M] Table I)" },
  length = { length, paper = L, tol = 1e-9, unit = "([M] Table I)" },
  end_mass = { mass, paper = m, tol = 1e-9, unit = "([M] Table I; §3.1.2: 3.3)" },
}
