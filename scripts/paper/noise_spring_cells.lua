-- title: Ten-point spring: the set-up, and the cells' stresses and nodes' forces as point 6 crosses a cell edge
-- source: York's dissertation [T], App. A.2, Figs 102, 103 and 104 (and §5.4.3)
-- look: (a) Fig 102: ten points numbered from the top, the top one held (zero
--   velocity), the bottom one 100 times the others' mass, gravity down; (b)
--   Fig 103: near the apex point 6 is about to cross a cell edge; each cell's
--   stress sigma_y and each node row's force f_y written beside them; (c) Fig
--   104: one step later point 6 is in the lower cell with its old stress, and
--   the force at the edge it crossed has turned from a small upward to a large
--   downward one - the kick that feeds the energy growth noise_spring shows
-- checks: the bottom point's mass 100 times the others' (Fig 102); the force at
--   the crossed edge's node row changes sign (Figs 103-104: +111 before, -3,940
--   after); our stresses and forces beside [T]'s (shown, not judged: [T]
--   gives no parameters, ours are noise_spring's, assets/lua/noise_spring.lua)
-- assumed: noise_spring's spring (its header), the papers' linear basis with
--   point quadrature
-- thumb: noise_spring_cells.png
local sp = require("noise_spring")
local sk = require("sketch")
local out = lamina.param("out", "out/noise_spring_cells")

local sim, s = sp.setup{}
local P0 = s:particles()
local ratio = P0.mass[P0.n] / P0.mass[1]
local function positions()
  local P = s:particles()
  local pts = {}
  for i = 1, P.n do pts[i] = {P.x[i], P.y[i]} end
  return pts
end
local crossing, prev, prev_pts
sim:every(sim.dt, function()
  if crossing then return end
  local now, pts = sp.probe(s), positions()
  if prev and now.row6 ~= prev.row6 then
    crossing = { before = prev, after = now, t = sim.t, from = prev.row6, to = now.row6,
                 pts_before = prev_pts, pts_after = pts }
  end
  prev, prev_pts = now, pts
end)
sim:run{ t_end = 0.6 }
assert(crossing, "point 6 did not cross a cell edge by t = 0.6")
local je = math.max(crossing.from, crossing.to)   -- the node row of the crossed edge
local edge = sp.Y0 + je * sp.h

local fig = lamina.figure{ width = 1200, height = 760, panels = {3, 1},
  title = "[T] Figs 102-104: the ten-point spring, and point 6 crossing a cell edge" }
-- (a) Fig 102: the set-up
fig:panel{ index = 1, window = {-0.12, 1.38, 0.32, 2.1}, title = "(a) Fig 102: set-up" }
fig:grid{ box = {0, 1.4, 0.2, 2.0}, cells = {2, 6} }
sk.wall(fig, {0, 2.0}, {0.2, 2.0}, { side = 1, hatch = 0.02, strokes = 8 })
fig:text{ text = "top: zero velocity BC", at = {0.1, 2.045}, align = "center" }
local pts0 = {}
for i = 1, P0.n do pts0[i] = {P0.x[i], P0.y[i]} end
fig:points{ points = pts0, style = "circle", size = 6, colour = "black" }
fig:points{ points = {pts0[P0.n]}, style = "dot", size = 12, colour = "exact" }
for _, i in ipairs{1, 6, P0.n} do
  fig:text{ text = string.format("material point %d", i), at = {0.21, P0.y[i] - 0.005} }
end
fig:text{ text = string.format("mass = %.0fx others", ratio), at = {0.21, P0.y[P0.n] - 0.035} }
sk.arrow(fig, {-0.06, 1.85}, {-0.06, 1.75}, "g")
sk.arrow(fig, {-0.1, 1.45}, {-0.04, 1.45}, "x")
sk.arrow(fig, {-0.1, 1.45}, {-0.1, 1.51}, "y")

-- (b), (c): the cells round the crossed edge, stresses and forces
local function cells(index, title, state, pts, paper)
  local y0, y1 = edge - 1.5 * sp.h, edge + 1.5 * sp.h
  fig:panel{ index = index, window = {-0.1, y0 - 0.02, 0.3, y1 + 0.02}, title = title, caption = paper }
  fig:grid{ box = {0, edge - sp.h, 0.2, edge + sp.h}, cells = {2, 2} }
  fig:polyline{ points = {{0, edge}, {0.2, edge}}, colour = "black", width = 2 }
  local vis = {}
  for i = 1, #pts do
    if pts[i][2] > y0 and pts[i][2] < y1 then
      vis[#vis + 1] = pts[i]
      fig:text{ text = tostring(i), at = {pts[i][1] - 0.012, pts[i][2] - 0.004}, align = "right",
                colour = i == 6 and "exact" or nil }
    end
  end
  fig:points{ points = vis, style = "circle", size = 7, colour = "black" }
  fig:points{ points = {pts[6]}, style = "dot", size = 8, colour = "exact" }
  for j = je - 1, je do
    fig:text{ text = string.format("sy = %.0f", state.sy[j] or 0),
              at = {0.11, sp.Y0 + (j + 0.5) * sp.h + 0.01} }
  end
  for j = je - 1, je + 1 do
    local f = state.fi[j] or 0
    local yn = sp.Y0 + j * sp.h
    fig:text{ text = string.format("fy = %.0f", f), at = {0.215, yn + 0.006} }
    if math.abs(f) > 0 then
      fig:arrows{ at = {{0.205, yn}}, dir = {{0, f > 0 and 1 or -1}},
                  length = 0.02 + 0.03 * math.min(1, math.abs(f) / 2000),
                  colour = f > 0 and "computed" or "exact", width = 2 }
    end
  end
end
cells(2, "(b) Fig 103: before point 6 crosses", crossing.before, crossing.pts_before,
      "[T]: sy 123,034 / 181,170; fy 66, 111, 3,114")
cells(3, "(c) Fig 104: after it crosses", crossing.after, crossing.pts_after,
      "[T]: sy 123,274 / 179,802; fy 2,183, -3,940, 5,123")
fig:write(out .. "/noise_spring_cells.png")

local fb, fa = crossing.before.fi[je] or 0, crossing.after.fi[je] or 0
print(string.format("point 6 crosses y = %.2f at t = %.5f; f_y at that node row %.1f -> %.1f; "
  .. "sy above %.0f -> %.0f, below %.0f -> %.0f", edge, crossing.t, fb, fa,
  crossing.before.sy[je] or 0, crossing.after.sy[je] or 0,
  crossing.before.sy[je - 1] or 0, crossing.after.sy[je - 1] or 0))
local function sign(x) return x > 0 and 1 or (x < 0 and -1 or 0) end
lamina.report{
  heavy_point_ratio = { ratio, paper = 100, tol = 1e-9, unit = "x the others' mass (Fig 102)" },
  edge_force_sign_change = { sign(fb) * sign(fa), paper = -1, tol = 0,
                             unit = "sign(before) x sign(after) (Figs 103-104: +111 -> -3,940)" },
  edge_fy_before = { fb, paper = 111, unit = "(Fig 103; our spring's parameters are assumed)" },
  edge_fy_after = { fa, paper = -3940, unit = "(Fig 104)" },
  crossing_time = crossing.t,
  state_hash = sim:hash(),
}
