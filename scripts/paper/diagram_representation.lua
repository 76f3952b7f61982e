-- title: How MPM represents a solid and a membrane: material points over the computational mesh
-- source: York, Sulsky & Schreyer 1999 (membranes), §2-3, Figs 1, 2 and 4; York, Sulsky & Schreyer 2000 (fluid-membrane), Figs 1 and 3; York's dissertation, Figs 7, 8, 20 and 23
-- look: (a) a physical solid and (b) its material points over the mesh, four
--   to an element, each standing for a quarter of the element (its square
--   drawn, the shaded volume of [M] Fig 4(b), the subdomains of [T] Fig 7); (c) a physical membrane
--   contour and (d) its single layer of material points over the same mesh,
--   with no ordered relation to the grid ([M] Fig 4(d)), about a third of a
--   cell apart ([M] §3: "fractions of one-third to one-tenth")
-- checks: on the points lamina seeds: a solid point's volume m/rho a quarter
--   of the element ([M] §3), four points in each element the body covers; a
--   membrane point's mass s rho t / N for the closed contour of length s with
--   N points ([M] §3: m_p = s rho / N, rho per unit area there)
-- assumed: the papers draw shapes without sizes: a disk of radius 0.32 and a
--   closed membrane contour (an ellipse 0.38 x 0.26), cells of 0.1
-- thumb: diagram_representation.png
local out = lamina.param("out", "out/diagram_representation")

local h, rho, rho_m, th = 0.1, 1.0, 0.5, 0.1
local sim = lamina.sim{ basis = "linear", domain = {0, 0, 2.0, 1.0}, cell = h, dt = 1e-5 }
local solid = sim:body{ material = lamina.elastic{ rho = rho, E = 1e4, nu = 0.3 }, ppc = 4, name = "solid",
                        region = lamina.disk{ center = {0.5, 0.5}, radius = 0.32 } }
local N = 60
local contour = function(u)
  local a = 2 * math.pi * u
  return 1.5 + 0.38 * math.cos(a), 0.5 + 0.26 * math.sin(a)
end
local mem = sim:membrane{ material = lamina.membrane{ rho = rho_m, E = 1e6, nu = 0, thickness = th },
                          curve = contour, count = N, name = "membrane" }
local S, M = solid:particles(), mem:particles()

-- the checks
local worst_vol, per_cell = 0, {}
for i = 1, S.n do
  worst_vol = math.max(worst_vol, math.abs(S.mass[i] / S.rho[i] - h * h / 4))
  local key = math.floor(S.x[i] / h) .. ":" .. math.floor(S.y[i] / h)
  per_cell[key] = (per_cell[key] or 0) + 1
end
local full, other = 0, 0
for _, c in pairs(per_cell) do if c == 4 then full = full + 1 else other = other + 1 end end
local s = 0   -- the contour's length, from the points (a closed polygon of N sides)
local sfine = 0
for k = 0, 4095 do
  local x0, y0 = contour(k / 4096)
  local x1, y1 = contour((k + 1) / 4096)
  sfine = sfine + math.sqrt((x1 - x0) ^ 2 + (y1 - y0) ^ 2)
end
for i = 1, M.n do
  local j = i % M.n + 1
  s = s + math.sqrt((M.x[j] - M.x[i]) ^ 2 + (M.y[j] - M.y[i]) ^ 2)
end
local worst_mass = 0
for i = 1, M.n do worst_mass = math.max(worst_mass, math.abs(M.mass[i] - sfine * rho_m * th / N)) end

local fig = lamina.figure{ width = 1100, height = 1000, panels = {2, 2},
  title = "[M] Figs 1, 2, 4 / [F] Figs 1, 3: a solid and a membrane, physical and MPM" }
local function mesh(x0) fig:grid{ box = {x0 - 0.5, 0, x0 + 0.5, 1.0}, cells = {10, 10} } end
local disk, ell = {}, {}
for k = 0, 120 do
  local a = 2 * math.pi * k / 120
  disk[#disk + 1] = {0.5 + 0.32 * math.cos(a), 0.5 + 0.32 * math.sin(a)}
  ell[#ell + 1] = {contour(k / 120)}
end
fig:panel{ index = 1, window = {0, 0, 1, 1}, title = "(a) physical solid" }
fig:polyline{ points = disk, colour = "black", width = 2.5 }
fig:panel{ index = 2, window = {0, 0, 1, 1}, title = "(b) MPM: points over the mesh, 4 per element",
           caption = string.format("volume m/rho = h^2/4 to %.1e; %d elements with 4 points", worst_vol, full) }
mesh(0.5)
fig:polyline{ points = disk, colour = "grey", dashed = true }
local pts = {}
for i = 1, S.n do
  pts[i] = {S.x[i], S.y[i]}
  local q = h / 4   -- the point's quarter of its element
  fig:polyline{ points = {{S.x[i] - q, S.y[i] - q}, {S.x[i] + q, S.y[i] - q}, {S.x[i] + q, S.y[i] + q},
                          {S.x[i] - q, S.y[i] + q}, {S.x[i] - q, S.y[i] - q}}, colour = {0.35, 0.7, 0.9, 0.6} }
end
fig:points{ points = pts, style = "dot", size = 5, colour = "computed" }
fig:panel{ index = 3, window = {1, 0, 2, 1}, title = "(c) physical membrane contour" }
fig:polyline{ points = ell, colour = "black", width = 2.5 }
fig:panel{ index = 4, window = {1, 0, 2, 1}, title = "(d) MPM: one layer of points over the mesh",
           caption = string.format("%d points, ds = %.3f (%.2f cells); m = s rho t / N to %.1e",
                                   N, sfine / N, sfine / N / h, worst_mass) }
mesh(1.5)
fig:polyline{ points = ell, colour = "grey", dashed = true }
local mp = {}
for i = 1, M.n do mp[i] = {M.x[i], M.y[i]} end
fig:points{ points = mp, style = "circle", size = 7, colour = "exact" }
fig:write(out .. "/diagram_representation.png")

print(string.format("solid: %d points, volume off h^2/4 by at most %.2e; %d elements with 4, %d with fewer; "
  .. "membrane: %d points, s = %.5f (polygon %.5f), ds = %.4f = %.3f cells, mass off s rho t / N by %.2e",
  S.n, worst_vol, full, other, N, sfine, s, sfine / N, sfine / N / h, worst_mass))
lamina.report{
  solid_point_volume = { worst_vol / (h * h / 4), ref = 0, tol = 1e-12,
                         unit = "largest |m/rho - h^2/4| / (h^2/4) ([M] §3: a quarter of the element)" },
  elements_with_four = full,
  membrane_point_mass = { worst_mass / (sfine * rho_m * th / N), ref = 0, tol = 1e-3,
                          unit = "largest |m - s rho t / N| / (s rho t / N) ([M] §3; tol: s from the curve's 4096 samples)" },
  spacing_cells = { sfine / N / h, unit = "cells ([M] §3: 1/10 to 1/3 used)" },
}
