-- title: Idealised spring-mass system: a rigid mass on a massless spring hung from a wall
-- source: York's dissertation §5.5.1, Fig 24
-- look: a spring of unstretched length L and constant k hangs from the wall,
--   the mass m at its end, gravity g downwards, y measured from the static
--   equilibrium position; beside it the values the MPM run takes (A, E, L, m, g)
-- checks: on the MPM set-up membrane_spring_mass seeds from these values: the
--   heavy point's mass 3.33 ([T] §5.5.2; 9990 times the other points', the
--   text's "10,000 times" shown beside it) and the
--   spring constant AE/L against [M] §3.2's k = 3.33e5; the period
--   2 pi sqrt(m/k) and the static deflection mg/k ([T] eq 5.11, ours, printed)
-- thumb: sketch_spring_mass.png
local sk = require("sketch")
local out = lamina.param("out", "out/sketch_spring_mass")

-- [T] §5.5.2: A = 0.1, E = 1e6, g = -250, L = 0.3, m = 3.33; rho 0.1 as membrane_spring_mass
local E, A, rho, L, m, g = 1e6, 0.1, 0.1, 0.3, 3.33, 250
local sim = lamina.sim{ basis = "linear", domain = {0, 0, 0.2, 2.0}, cell = 0.1, dt = 1e-5,
                        gravity = {0, -g}, boundary = { left = "symmetry", right = "symmetry" } }
local s = sim:membrane{ force = "point", count = 10, end_mass = m, name = "spring",
                        material = lamina.membrane{ rho = rho, E = E, nu = 0, thickness = A },
                        curve = lamina.segment{ from = {0.1, 1.99}, to = {0.1, 1.69} } }
local p = s:particles()
local n = #p.x
local ratio = p.mass[n] / p.mass[1]
local length = p.y[1] - p.y[n]
local k = A * E / length
local T = 2 * math.pi * math.sqrt(m / k)
local d = m * g / k

local fig = lamina.figure{ width = 760, height = 620, panels = {1, 1},
  title = "[T] Fig 24: idealised spring-mass system" }
fig:panel{ index = 1, window = {-0.6, -1.25, 1.0, 0.15},
           caption = string.format("seeded: k = AE/L = %.4g, m = %.0f x a spring point; T = %.5f",
                                   k, ratio, T) }
sk.wall(fig, {-0.2, 0}, {0.2, 0}, { side = 1, hatch = 0.05, strokes = 10 })
sk.spring(fig, {0, 0}, {0, -0.6}, { coils = 7, width = 0.06 })
sk.box(fig, -0.1, -0.8, 0.1, -0.6, { width = 2 })
fig:text{ text = "m", at = {0, -0.71}, align = "center" }
fig:text{ text = "k, L", at = {0.1, -0.3} }
sk.dim(fig, {-0.25, 0}, {-0.25, -0.6}, "L", { gap = -0.03, align = "right" })
sk.arrow(fig, {-0.45, -0.4}, {-0.45, -0.65}, "g")
fig:polyline{ points = {{0.12, -0.7}, {0.4, -0.7}}, colour = "grey", dashed = true }
sk.arrow(fig, {0.35, -0.7}, {0.35, -0.9}, "y, from the static equilibrium")
local rows = { {"A", "0.1"}, {"E", "1e6"}, {"L", "0.3"}, {"m", "3.33"}, {"g", "-250"} }
fig:text{ text = "[T] §5.5.2", at = {0.45, -0.05} }
for i, r in ipairs(rows) do
  fig:text{ text = r[1], at = {0.5, -0.05 - 0.1 * i} }
  fig:text{ text = r[2], at = {0.62, -0.05 - 0.1 * i} }
end
fig:write(out .. "/sketch_spring_mass.png")

print(string.format("mass ratio %.4f, L %.6f, k %.6g, T %.6f, static deflection %.6f", ratio, length, k, T, d))
lamina.report{
  end_mass = { p.mass[n], paper = 3.33, tol = 1e-9, unit = "([T] §5.5.2)" },
  -- 3.33 over a point's rho A L/9 = 1/3000 is 9990: "10,000 times" is the
  -- paper's round figure (its 3.33 rounds 10/3), shown, not judged
  mass_ratio = { ratio, paper = 10000, unit = "x a spring point ([T] §5.5.2: 10,000 times)" },
  spring_constant = { k, paper = 3.33e5, tol = 0.005e5, unit = "AE/L ([M] §3.2: k = 3.33e5)" },
  period = { T, unit = "s, 2 pi sqrt(m/k) (ours)" },
  static_deflection = { d, unit = "mg/k (ours)" },
}
