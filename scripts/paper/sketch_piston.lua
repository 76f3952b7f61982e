-- title: Piston-container problem: the sketch and the MPM set-up
-- source: York, Sulsky & Schreyer 2000 (fluid-membrane), §4.2, Figs 7 and 8; York's dissertation §6.1, Figs 44 and 45
-- look: top, the problem ([F] Fig 7): a container of compressible fluid
--   (density rho, bulk modulus beta) closed by a piston of mass m and area A,
--   held by a massless spring K of length L from the wall. Below, the MPM
--   set-up ([F] Fig 8) as gas_piston_container seeds it: fluid points (4 a
--   cell), the spring's membrane points, the heavy point that is the piston.
-- checks: the heavy point's mass 100 times the spring's other points' ([F]
--   §4.2), measured on the seeded points; the piston's period in a vacuum
--   2 pi sqrt(m/K) = 0.628 s for m = 1 ([T] §6.1.2), and the roots of the
--   frequency equation ([F] eq 27) beside Table I's omega and periods (shown,
--   not judged: the paper does not say how it solved eq 27, and its omega for
--   m = 0.1 is 0.025 % from the root; gas_piston_container checks the MPM's
--   periods against them)
-- assumed: gas_piston_container's set-up (its header): cells of 1, a
--   2-long spring of 3 points; [T] Fig 45's axis runs 0-40 with its cells not stated
-- thumb: sketch_piston.png
local sk = require("sketch")
local out = lamina.param("out", "out/sketch_piston")

local L, A, K, rho, beta = 20, 1, 100, 1e-4, 1.58e6
local c = math.sqrt(beta / rho)
local function root(m)   -- [F] eq 27's first root, by bisection below the first pole of cot
  local function F(w) return w * w * m - K - rho * w * c * A / math.tan(w * L / c) end
  local a, b = 1e-6, math.pi * c / L * (1 - 1e-12)
  for _ = 1, 200 do
    local mid = 0.5 * (a + b)
    if F(a) * F(mid) <= 0 then b = mid else a = mid end
  end
  return 0.5 * (a + b)
end
local w01, w10 = root(0.1), root(1.0)

-- the MPM set-up as gas_piston_container seeds it (m = 1)
local m, Ls, n = 1.0, 2, 3
local sim = lamina.sim{ basis = "linear", domain = {0, 0, L + Ls, 1}, cell = 1, dt = 0.5 / c,
                        boundary = { left = "fixed", right = "fixed", bottom = "symmetry", top = "symmetry" } }
local fluid = sim:body{ material = lamina.linear_fluid{ rho = rho, beta = beta },
                        region = lamina.rect{ x0 = 0, y0 = 0, x1 = L, y1 = 1 }, ppc = 4 }
local spring = sim:membrane{ force = "point", count = n, end_mass = m, name = "spring",
  material = lamina.membrane{ rho = m / (100 * A * Ls / (n - 1)), E = K * Ls / A, nu = 0, thickness = A },
  curve = lamina.segment{ from = {L + Ls, 0.5}, to = {L, 0.5} } }
local fp, sp = fluid:particles(), spring:particles()
local ratio = sp.mass[n] / sp.mass[1]

local fig = lamina.figure{ width = 1000, height = 560, panels = {1, 2},
  title = "[F] Figs 7 and 8 / [T] Figs 44 and 45: piston-container problem" }
-- (top) the problem
fig:panel{ index = 1, window = {-0.6, -0.9, 12.6, 3.3}, title = "the problem ([F] Fig 7)" }
fig:polyline{ points = {{0, 0}, {11, 0}}, colour = "black", width = 2 }
fig:polyline{ points = {{0, 2}, {11, 2}}, colour = "black", width = 2 }
sk.wall(fig, {0, 2}, {0, 0}, { side = -1, hatch = 0.35, strokes = 6 })
sk.wall(fig, {11, 0}, {11, 2}, { side = -1, hatch = 0.35, strokes = 6 })
sk.box(fig, 7, 0.05, 7.5, 1.95, { width = 2.5 })
sk.spring(fig, {7.5, 1}, {11, 1}, { coils = 6, width = 0.3 })
fig:text{ text = "fluid: density rho, bulk modulus beta", at = {3.5, 1.0}, align = "center" }
fig:text{ text = "piston: mass m, area A", at = {7.25, 2.3}, align = "center" }
fig:text{ text = "spring K (massless)", at = {9.25, 1.55}, align = "center" }
-- the papers' text calls L the spring's length, but eq 27's cot(omega L / c)
-- and L = 20 make it the fluid column's
sk.dim(fig, {0, -0.35}, {7, -0.35}, "L = 20: the fluid column (eq 27)", { gap = -0.35 })
-- (bottom) the MPM set-up
fig:panel{ index = 2, window = {-0.5, -1.0, L + Ls + 0.5, 1.6},
           title = "the MPM set-up ([F] Fig 8), as lamina seeds it" }
fig:grid{ box = {0, 0, L + Ls, 1}, cells = {L + Ls, 1} }
local fpts, spts = {}, {}
for i = 1, #fp.x do fpts[i] = {fp.x[i], fp.y[i]} end
for i = 1, n - 1 do spts[i] = {sp.x[i], sp.y[i]} end
fig:points{ points = fpts, style = "dot", size = 5, colour = "computed" }
fig:points{ points = spts, style = "circle", size = 8, colour = "black" }
fig:points{ points = {{sp.x[n], sp.y[n]}}, style = "dot", size = 12, colour = "exact" }
for k = 0, L + Ls, 2 do fig:text{ text = tostring(k), at = {k, -0.45}, align = "center" } end
fig:text{ text = "fluid point (blue)", at = {2, 1.25} }
fig:text{ text = "spring (membrane) point (circle)", at = {13, 1.25} }
fig:text{ text = "\"heavy\" point: the piston (vermilion)", at = {L + Ls, -0.9}, align = "right" }
fig:write(out .. "/sketch_piston.png")

local T0 = 2 * math.pi * math.sqrt(1 / K)
print(string.format("omega %.2f / %.2f (Table I 886.2 / 281.2), periods %.6f / %.6f (0.00709 / 0.02234), "
  .. "vacuum %.4f (0.628), heavy/spring point mass %.3f", w01, w10, 2 * math.pi / w01, 2 * math.pi / w10, T0, ratio))
lamina.report{
  heavy_point_ratio = { ratio, paper = 100, tol = 1e-9, unit = "x a spring point's mass ([F] §4.2)" },
  vacuum_period = { T0, paper = 0.628, tol = 0.0005, unit = "s, m = 1 ([T] §6.1.2)" },
  omega_m0_1 = { w01, paper = 886.2, unit = "rad/s, root of eq 27 (Table I)" },
  omega_m1_0 = { w10, paper = 281.2, unit = "rad/s, root of eq 27 (Table I)" },
  period_m0_1 = { 2 * math.pi / w01, paper = 0.00709, unit = "s (Table I)" },
  period_m1_0 = { 2 * math.pi / w10, paper = 0.02234, unit = "s (Table I)" },
  fluid_points = #fp.x,
}
