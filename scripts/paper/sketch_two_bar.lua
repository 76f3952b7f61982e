-- title: Two-bar impact: the initial conditions and the MPM set-up
-- source: York, Sulsky & Schreyer 1999 (membranes), §4.1, Fig 17; York 1997
--   (dissertation), App. A.1.2, Fig 92, input deck A.4.12
-- look: left, the problem ([M] Fig 17, [T] Fig 92): two equal elastic bars,
--   the left one moving at v_l0 towards the right one at rest, "for both
--   bars: E = 1e5, plane stress, nu = 0.3, rho = 1"; right, the set-up as
--   contact_two_bar seeds it from the deck: the 5 x 5 box of 20 x 20 cells
--   with fixed walls, 4 points a cell in each bar
-- checks: measured on the seeded points (contact_scenes.two_bar, the scene
--   contact_two_bar and contact_normals run): each bar's mass against rho
--   times the deck's 1.25 x 4.5 (5.625, to round-off), the gap between the
--   bars' material edges (the points' extent plus half a spacing) against
--   the deck's 0.5, and the bars' velocities against the deck's 2 and 0
--   (exact); the deck's dt beside the Courant limit h / c of the plane-stress
--   wave speed c = sqrt(E / ((1 - nu^2) rho)) (printed)
-- assumed: v_l0 = 2 from the deck (vrx(1) = 2.0); the figures give no number
-- thumb: sketch_two_bar.png
local sk = require("sketch")
local out = lamina.param("out", "out/sketch_two_bar")

local E, nu, rho, v0 = 1e5, 0.3, 1, 2
local sim, left, right = require("contact_scenes").two_bar{ release = true }
local function extent(b)
  local P = b:particles()
  local x0, x1, m = math.huge, -math.huge, 0
  for i = 1, #P.x do
    x0, x1, m = math.min(x0, P.x[i]), math.max(x1, P.x[i]), m + P.mass[i]
  end
  return x0, x1, m, P
end
local _, lx1, lm, LP = extent(left)
local rx0, _, rm, RP = extent(right)
local s = 0.25 / 2   -- the point spacing at 4 a cell
local gap = (rx0 - s / 2) - (lx1 + s / 2)
local vl, vr = left:velocity(), right:velocity()
local c = math.sqrt(E / ((1 - nu * nu) * rho))

local fig = lamina.figure{ width = 1000, height = 520, panels = {2, 1},
  title = "[M] Fig 17 / [T] Fig 92: two-bar impact, initial conditions" }
fig:panel{ index = 1, window = {-0.3, -0.9, 5.3, 5.4}, title = "the problem" }
sk.box(fig, 1, 0.25, 2.25, 4.75, { width = 2 })
sk.box(fig, 2.75, 0.25, 4, 4.75, { width = 2 })
sk.arrow(fig, {1.2, 2.5}, {2.05, 2.5}, nil, { width = 2.5 })
fig:text{ text = "v_l0", at = {1.625, 2.75}, align = "center" }
fig:text{ text = "v_r0 = 0", at = {3.375, 2.75}, align = "center" }
fig:text{ text = "left bar", at = {1.625, 4.95}, align = "center" }
fig:text{ text = "right bar", at = {3.375, 4.95}, align = "center" }
fig:text{ text = "for both bars: E = 1e5, plane stress, nu = 0.3, rho = 1", at = {2.5, -0.55},
          align = "center" }
fig:panel{ index = 2, window = {-0.3, -0.9, 5.3, 5.4}, title = "the MPM set-up, as lamina seeds it" }
fig:grid{ box = {0, 0, 5, 5}, cells = {20, 20} }
local lp, rp = {}, {}
for i = 1, #LP.x do lp[i] = {LP.x[i], LP.y[i]} end
for i = 1, #RP.x do rp[i] = {RP.x[i], RP.y[i]} end
fig:points{ points = lp, style = "dot", size = 3, colour = "computed" }
fig:points{ points = rp, style = "dot", size = 3, colour = "exact" }
sk.dim(fig, {2.25, 0.05}, {2.75, 0.05}, string.format("gap %.3g", gap), { gap = -0.3 })
fig:text{ text = string.format("v = %g", vl), at = {1.625, 5.1}, align = "center" }
fig:text{ text = string.format("v = %g", vr), at = {3.375, 5.1}, align = "center" }
fig:text{ text = "cell 0.25, 4 points a cell, fixed walls", at = {2.5, -0.55}, align = "center" }
fig:write(out .. "/sketch_two_bar.png")

print(string.format("masses %.15g / %.15g (rho x 1.25 x 4.5 = 5.625), gap %.15g (0.5), v %g / %g, "
  .. "dt 7e-4 against h / c = %.4g (c = %.1f)", lm, rm, gap, vl, vr, 0.25 / c, c))
lamina.report{
  mass_left = { lm, paper = 5.625, tol = 1e-12, unit = "rho ([M] Fig 17) x the deck's 1.25 x 4.5 ([T] A.4.12)" },
  mass_right = { rm, paper = 5.625, tol = 1e-12, unit = "rho ([M] Fig 17) x the deck's 1.25 x 4.5 ([T] A.4.12)" },
  gap = { gap, paper = 0.5, tol = 1e-12, unit = "between the bars' edges ([T] A.4.12)" },
  v_left = { vl, paper = v0, tol = 0, unit = "v_l0 ([T] A.4.12: vrx(1) = 2.0)" },
  v_right = { vr, paper = 0, tol = 0, unit = "v_r0 ([M] Fig 17)" },
  courant = { 7e-4 / (0.25 / c), unit = "the deck's dt over h / c" },
  state_hash = sim:hash(),
}
