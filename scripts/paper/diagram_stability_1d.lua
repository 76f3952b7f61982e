-- title: The one-dimensional problem of the stability analysis: its notation and each element's shape functions
-- source: York's dissertation [T] §8.4, Figs 89 and 90 (eq 8.1)
-- look: (a) Fig 89: a row of grid nodes j-2 ... j+2, Delta x apart, and the
--   material points p-2 ... p+2 between them, one per cell, all at the same
--   place in their cells (here a quarter cell from the left node, as the
--   analysis allows: "this does not assume that they are in the center of
--   the cell"); (b) Fig 90: each element's two linear shape functions, N_j
--   falling from 1 at node j to 0 at j+1 and 1 - N_j rising, point p's
--   values N1 = N_j(x_p) and N2 = 1 - N1 marked on them
-- checks: eq 8.1, N1 = N_j(x_p) = (x_{j+1} - x_p) / Delta x and N2 = 1 - N1,
--   against lamina's own linear basis (the bilinear of lamina.normals, whose
--   phi is sum_I phi_I N_I, along a cell's edge) at 101 places, to round-off;
--   and the analysis' consequence that, with equal spacing, every interior
--   node's mass is m ("the initial grid masses, M, are equal to m"): the
--   nodal masses sum_p m N_j(x_p) over the points lamina seeds for
--   stability_bar's bar (Box 14, here 9 points), to round-off
-- assumed: Delta x = 1 and m = 1 (Box 14's); the offset a quarter cell
-- thumb: diagram_stability_1d.png
local sk = require("sketch")
local bar = require("stability_bar")
local out = lamina.param("out", "out/diagram_stability_1d")

-- eq 8.1 against lamina's bilinear along the edge s = 0 of a unit cell
local r = lamina.normals{ points = {{0.2, 0.3}, {0.5, 0.6}, {0.8, 0.4}}, box = {0, 0, 1, 1},
                          basis = "linear", seed = 3 }
local worst_n = 0
for k = 0, 100 do
  local x = k / 100
  local n1 = (1 - x) / 1          -- (x_{j+1} - x_p) / Delta x, node j at 0
  local n2 = 1 - n1
  worst_n = math.max(worst_n, math.abs(r.phi_at(x, 0) - (r.phi[1] * n1 + r.phi[2] * n2)))
end

-- the nodal masses of an equally spaced bar (lamina's seeding of Box 14's
-- bar, one point a cell at the same offset), from eq 8.1
local offset, npts = 0.25, 9
bar.start.quarter = offset
local _, _, bsim, body = bar.run("quarter", 1.0, "musl", 0, npts)
local P = body:particles()
local M = {}
for i = 1, P.n do
  local j = math.floor(P.x[i] / bar.h)
  local n1 = ((j + 1) * bar.h - P.x[i]) / bar.h
  M[j] = (M[j] or 0) + P.mass[i] * n1
  M[j + 1] = (M[j + 1] or 0) + P.mass[i] * (1 - n1)
end
local worst_m, m = 0, P.mass[1]
for j = 1, npts - 1 do worst_m = math.max(worst_m, math.abs(M[j] - m) / m) end

local fig = lamina.figure{ width = 1100, height = 620, panels = {1, 2},
  title = "[T] Figs 89 and 90: the one-dimensional problem of the stability analysis" }
-- (a) Fig 89: nodes and points
fig:panel{ index = 1, window = {-0.6, -0.7, 5.6, 0.9}, title = "(a) Fig 89: one-dimensional problem notation",
           caption = string.format("points one per cell, a quarter cell from node j; interior nodal mass "
                                   .. "sum m N = m to %.0e", worst_m) }
fig:polyline{ points = {{-0.5, 0}, {5.5, 0}}, colour = "black", width = 1.5 }
local nodes, pts = {}, {}
local names = { "j-2", "j-1", "j", "j+1", "j+2", "j+3" }
local pnames = { "p-2", "p-1", "p", "p+1", "p+2" }
for k = 0, 5 do
  nodes[#nodes + 1] = {k, 0}
  fig:text{ text = names[k + 1], at = {k, -0.35}, align = "center" }
end
for k = 0, 4 do
  pts[#pts + 1] = {k + offset, 0}
  fig:text{ text = pnames[k + 1], at = {k + offset, 0.22}, align = "center" }
end
fig:points{ points = nodes, style = "circle", size = 9, colour = "black" }
fig:points{ points = pts, style = "dot", size = 9, colour = "computed" }
sk.dim(fig, {2, -0.5}, {3, -0.5}, "Delta x", { gap = -0.12 })
fig:text{ text = "x", at = {5.45, 0.12} }
fig:points{ points = {{3.6, -0.62}}, style = "circle", size = 9, colour = "black" }
fig:text{ text = "grid node", at = {3.7, -0.66} }
fig:points{ points = {{4.5, -0.62}}, style = "dot", size = 9, colour = "computed" }
fig:text{ text = "material point", at = {4.6, -0.66} }
-- (b) Fig 90: each element's shape functions
fig:panel{ index = 2, window = {-0.6, -0.45, 5.6, 1.35}, title = "(b) Fig 90: shape functions of each element",
           caption = string.format("eq 8.1 N1 = (x_{j+1} - x_p) / Delta x, N2 = 1 - N1 against lamina's "
                                   .. "linear basis: to %.0e", worst_n) }
fig:polyline{ points = {{-0.5, 0}, {5.5, 0}}, colour = "black", width = 1 }
for k = 0, 4 do
  fig:polyline{ points = {{k, 1}, {k + 1, 0}}, colour = k == 2 and "computed" or "grey",
                width = k == 2 and 2 or 1 }
  fig:polyline{ points = {{k, 0}, {k + 1, 1}}, colour = k == 2 and "exact" or "grey",
                width = k == 2 and 2 or 1, dashed = true }
end
fig:points{ points = nodes, style = "circle", size = 7, colour = "black" }
local xp = 2 + offset
fig:polyline{ points = {{xp, 0}, {xp, 1 - offset}}, colour = "grey", width = 1 }
fig:points{ points = {{xp, 1 - offset}, {xp, offset}}, style = "dot", size = 8, colour = "black" }
fig:text{ text = "N1 = N_j(x_p)", at = {xp + 0.08, 1 - offset + 0.05} }
fig:text{ text = "N2 = 1 - N_j", at = {xp + 0.08, offset - 0.12} }
fig:text{ text = "N_j", at = {2.05, 1.08} }
fig:text{ text = "j", at = {2, -0.25}, align = "center" }
fig:text{ text = "j+1", at = {3, -0.25}, align = "center" }
fig:text{ text = "p", at = {xp, -0.25}, align = "center" }
fig:write(out .. "/diagram_stability_1d.png")

print(string.format("eq 8.1 against lamina's linear basis: %.2e; interior nodal masses m to %.2e",
                    worst_n, worst_m))
lamina.report{
  shape_eq_8_1 = { worst_n, ref = 0, tol = 1e-12,
                   unit = "largest |phi(x) - (phi_j N1 + phi_j+1 N2)| along a cell ([T] eq 8.1; round-off)" },
  nodal_mass = { worst_m, ref = 0, tol = 1e-12,
                 unit = "largest |M_j - m| / m over the interior nodes ([T] §8.4: M = m; round-off)" },
  state_hash = bsim:hash(),
}
