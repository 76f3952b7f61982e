-- title: Sod's shock tube problem: the set-up, and the exact solution its numbers come from
-- source: York, Sulsky & Schreyer 2000 (fluid-membrane), §4.1, Fig 5; York's dissertation, Fig 11
-- look: top, the tube: a diaphragm at x = 0.5 between gas at rest with rho = 1,
--   p = 1 (left) and rho = 0.125, p = 0.1 (right), gamma = 1.4; the diaphragm
--   breaks at t = 0. Below, the exact Riemann solution at t = 0.143, when the
--   shock has travelled the 0.25 the papers let it: rarefaction, contact, shock
--   at x = 0.75.
-- checks: from the exact Riemann solution (assets/lua/riemann.lua, ours):
--   the shock strength p2/p1 (paper "approximately 3.0"), the shock speed
--   ("about 1.75") and the time to travel 0.25 ("0.143 s"), [F] §4.1 and
--   [T]; tolerances half a unit of the last digit the papers print
-- thumb: sketch_sod.png
local riemann = require("riemann")
local sk = require("sketch")
local out = lamina.param("out", "out/sketch_sod")

local s = riemann.solve{ left = {1, 0, 1}, right = {0.125, 0, 0.1}, gamma = 1.4 }
local strength = s.p_star / 0.1
local speed = s.shock_speed
local t_travel = 0.25 / speed

local fig = lamina.figure{ width = 900, height = 330, panels = {1, 1},
  title = "[F] Fig 5 / [T] Fig 11: Sod's shock tube, initial conditions" }
fig:panel{ index = 1, window = {-0.05, -0.12, 1.05, 0.36},
           caption = string.format("exact solution (ours): p2/p1 = %.3f, shock speed %.4f, "
                                   .. "0.25 travelled at t = %.4f", strength, speed, t_travel) }
fig:polyline{ points = {{0, 0}, {1, 0}}, colour = "black", width = 2 }
fig:polyline{ points = {{0, 0.2}, {1, 0.2}}, colour = "black", width = 2 }
sk.wall(fig, {0, 0.2}, {0, 0}, { side = -1, hatch = 0.03, strokes = 5 })
sk.wall(fig, {1, 0}, {1, 0.2}, { side = -1, hatch = 0.03, strokes = 5 })
fig:polyline{ points = {{0.5, 0}, {0.5, 0.2}}, colour = "exact", width = 2.5, dashed = true }
fig:text{ text = "diaphragm", at = {0.5, 0.23}, align = "center", colour = "exact" }
fig:text{ text = "rho = 1.0,  p = 1.0,  u = 0", at = {0.25, 0.09}, align = "center" }
fig:text{ text = "rho = 0.125,  p = 0.1,  u = 0", at = {0.75, 0.09}, align = "center" }
fig:text{ text = "gamma = 1.4", at = {0.5, 0.3}, align = "center" }
fig:text{ text = "0", at = {0, -0.07}, align = "center" }
fig:text{ text = "0.5", at = {0.5, -0.07}, align = "center" }
fig:text{ text = "1.0", at = {1, -0.07}, align = "center" }
sk.arrow(fig, {0.5, -0.05}, {0.62, -0.05}, "x", { dy = -0.01 })
fig:write(out .. "/sketch_sod.png")

-- the exact solution at t = 0.143 (what the set-up leads to; [F] Fig 6 shows the MPM's)
local xs, rho, p, u = {}, {}, {}, {}
for i = 0, 400 do
  local x = i / 400
  local r, v, pp = s:sample((x - 0.5) / 0.143)
  xs[#xs + 1], rho[#rho + 1], u[#u + 1], p[#p + 1] = x, r, v, pp
end
lamina.plot{ file = out .. "/exact_t0.143.png", width = 900, height = 400, csv = true,
             title = "Exact solution at t = 0.143 (ours): the shock at x = 0.75",
             xlabel = "x", ylabel = "rho, u, p", legend = "best", yrange = {0, 1.1},
             series = { { x = xs, y = rho, label = "density" },
                        { x = xs, y = u, label = "velocity" },
                        { x = xs, y = p, label = "pressure" },
                        { x = {0.75, 0.75}, y = {0, 1.05}, label = "x = 0.5 + 0.25", dashed = true,
                          color = 8 } } }

print(string.format("shock strength %.4f, speed %.5f, time to 0.25: %.5f", strength, speed, t_travel))
lamina.report{
  shock_strength = { strength, paper = 3.0, tol = 0.05, unit = "p2/p1 ([F] §4.1: approximately 3.0)" },
  shock_speed = { speed, paper = 1.75, tol = 0.005, unit = "([F] §4.1: about 1.75)" },
  time_to_0_25 = { t_travel, paper = 0.143, tol = 0.0005, unit = "s ([F] §4.1)" },
}
