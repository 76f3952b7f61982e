-- title: The ghost cell: a cell holding a single membrane point is solved together with its neighbours
-- source: York's dissertation [T] §7.8, Fig 88 (and §7.7: "the region considered was expanded to a group of four cells")
-- look: an arc of ten points across a grid of 4 x 2 cells; three cells hold
--   a single point, where one cell's system can draw no contour ([T]: "the
--   single-cell-based method has no way of defining a contour with only one
--   particle"); each is solved with the block of 2 x 2 cells around it (the
--   ghost cell, dashed), which holds more points, and its normal (solid)
--   follows the exact one (dashed)
-- checks: lamina.normals{method = "mass_matrix", cells}: every cell with a
--   single point solved in a merged 2 x 2 block ([T]'s four cells) holding at
--   least three points; the largest normal error at those points (printed:
--   [T] gives no number)
-- assumed: the arc (radius 1.3 about (1, -0.6), points 9 degrees apart) and
--   the grid (cells 0.5) are ours; the random point from seed 1
-- thumb: normals_ghost_cell.png
local nu = require("normals_util")
local out = lamina.param("out", "out/normals_ghost_cell")

local cx, cy, R = 1, -0.6, 1.3
local pts, ex = {}, {}
for k = 0, 9 do
  local a = math.rad(130 - 9 * k)
  pts[#pts + 1], ex[#ex + 1] = {cx + R * math.cos(a), cy + R * math.sin(a)}, {math.cos(a), math.sin(a)}
end
local h = 0.5
local r = lamina.normals{ points = pts, box = {0, 0, 2, 1}, cells = {4, 2}, method = "mass_matrix",
                          seed = 1, orient = {cx, cy} }
-- the cells holding one point, and the element that solved them
local function cell_of(p) return math.floor(p[1] / h) + 1, math.floor(p[2] / h) + 1 end
local count = {}
for _, p in ipairs(pts) do
  local i, j = cell_of(p)
  local key = string.format("%d:%d", i, j)
  count[key] = (count[key] or 0) + 1
end
local singles, all_merged, fewest, worst = 0, true, math.huge, 0
local fig = lamina.figure{ width = 1100, height = 620, panels = {1, 1},
  title = "[T] Fig 88: the ghost cell" }
fig:panel{ index = 1, window = {-0.05, -0.05, 2.05, 1.05} }
fig:grid{ box = {0, 0, 2, 1}, cells = {4, 2} }
local arc = {}
for k = 0, 60 do
  local a = math.rad(135 - 95 * k / 60)
  arc[#arc + 1] = {cx + R * math.cos(a), cy + R * math.sin(a)}
end
fig:polyline{ points = arc, dashed = true }
for _, e in ipairs(r.elements) do
  if count[string.format("%d:%d", e.cell[1], e.cell[2])] == 1 then
    singles = singles + 1
    all_merged = all_merged and e.merged and e.size == 2
    fewest = math.min(fewest, e.points)
    local x0, y0 = (e.block[1] - 1) * h, (e.block[2] - 1) * h
    fig:polyline{ points = {{x0 + 0.01, y0 + 0.01}, {x0 + 2 * h - 0.01, y0 + 0.01}, {x0 + 2 * h - 0.01, y0 + 2 * h - 0.01},
                            {x0 + 0.01, y0 + 2 * h - 0.01}, {x0 + 0.01, y0 + 0.01}},
                  colour = "exact", dashed = true, width = 1.5 }
    local x1, y1 = (e.cell[1] - 1) * h, (e.cell[2] - 1) * h
    fig:polyline{ points = {{x1, y1}, {x1 + h, y1}, {x1 + h, y1 + h}, {x1, y1 + h}, {x1, y1}},
                  colour = "black", width = 2.5 }
    for k, p in ipairs(pts) do
      local i, j = cell_of(p)
      if i == e.cell[1] and j == e.cell[2] then
        worst = math.max(worst, math.deg(nu.angle(r.normals[k], ex[k])))
      end
    end
  end
end
fig:arrows{ at = pts, dir = ex, length = 0.15, style = "dashed" }
fig:arrows{ at = pts, dir = r.normals, length = 0.15 }
fig:points{ points = pts, style = "circle" }
fig:caption{ text = string.format("bold: cells with a single point (%d); dashed: the 2 x 2 ghost cell each is solved in "
                                  .. "(at least %d points); their largest normal error %.1f deg", singles, fewest, worst) }
fig:write(out .. "/normals_ghost_cell.png")

print(string.format("%d single-point cells, all merged into 2 x 2 blocks: %s, fewest points in a block %d, "
  .. "largest error there %.2f deg", singles, tostring(all_merged), fewest, worst))
lamina.report{
  single_point_cells = singles,
  merged_2x2 = { all_merged and 1 or 0, ref = 1, tol = 0, unit = "(1: every single-point cell solved in a 2 x 2 block)" },
  block_has_three = { fewest >= 3 and 1 or 0, ref = 1, tol = 0,
                      unit = string.format("(1: every ghost cell holds at least 3 points; fewest %d)", fewest) },
  max_error_single = { worst, unit = "deg at the single points ([T] gives none)" },
}
