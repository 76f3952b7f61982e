-- title: The dissertation's normal variants on a cylinder at the first step: colour, quadratic colour, mass matrix, connectivity (no interior fluid)
-- source: York's dissertation [T] §7.5.1, Fig 66 (a), Fig 67 (a), Fig 68 (a) and Fig 72 (a-b):
--   the model problem, a circular cylinder of radius 1.0, normals before any deformation
-- look: the first quadrant of the cylinder, its membrane points (open
--   circles), exact normals dashed (vermilion), computed ones solid (blue).
--   (a) the simple colour function ([T] §7.1) and (b) the quadratic colour
--   function (§7.2) turn their normals wherever the points cross a cell
--   line: with only membrane points the colour's gradient is poorly defined
--   ([T]: "unacceptable", "poor"); (c) the mass matrix method (§7.4, per
--   cell) and (d) the normals from the points' connectivity agree with the
--   exact ones ([T]: "only a small difference" between them).
-- checks: each method's largest and median angle error over the quadrant's
--   points; [T] gives no numbers, only the verdicts above, which the numbers
--   are set beside.
-- assumed: [T] gives neither the grid nor the number of points: cells of
--   0.1 on [-1.5, 1.5]^2 (the dynamic test's boundary at x, y = 1.5, §7.5.2),
--   128 points evenly spaced on the whole circle (half a cell apart), the
--   whole circle used (as [T] did for the cubic method) so that the colour
--   methods need no symmetry conditions, and the first quadrant drawn. The
--   extra (colour 0) point of the mass matrix method is lamina's seeded
--   random point per cell (seed 1); normals are turned to point outward
--   (their sign is arbitrary). Connectivity: the direction x_{p+1} - x_{p-1}
--   turned by 90 degrees ([N] §8). Not reproduced: the 4 and 16 points-per-cell
--   fluid inside (Figs 66 (b), 67 (b), 68 (b), 69), which lamina's colour
--   variants do not take, and the cubic method (Figs 70-71), whose equations
--   are lost in the text.
-- thumb: normals_variants_cylinder.png
local nu = require("normals_util")
local out = lamina.param("out", "out/normals_variants_cylinder")

local R, h, n = 1.0, 0.1, 128
local pts, ex = {}, {}
for k = 0, n - 1 do
  local a = 2 * math.pi * (k + 0.5) / n
  pts[#pts + 1], ex[#ex + 1] = {R * math.cos(a), R * math.sin(a)}, {math.cos(a), math.sin(a)}
end
local box = {-1.5, -1.5, 1.5, 1.5}
local cells = {math.floor(3 / h + 0.5), math.floor(3 / h + 0.5)}
local q = n // 4                        -- the first quadrant's points: 1 .. q

local function by_method(method)
  return lamina.normals{points = pts, box = box, cells = cells, method = method, seed = 1,
                        orient = {0, 0}}.normals
end

local function by_connectivity()
  local ns = {}
  for k = 1, n do
    local a, b = pts[(k - 2) % n + 1], pts[k % n + 1]
    local tx, ty = b[1] - a[1], b[2] - a[2]
    local l = math.sqrt(tx * tx + ty * ty)
    ns[k] = {ty / l, -tx / l}           -- the tangent turned by -90 degrees: outward here
  end
  return ns
end

local function quadrant_errors(ns)
  local v, mx = {}, 0
  for k = 1, q do
    v[k] = math.deg(nu.angle(ns[k], ex[k]))
    mx = math.max(mx, v[k])
  end
  return mx, nu.median(v)
end

local panels = {
  {"colour", "(a) Fig 67(a): simple colour function", "unacceptable"},
  {"quadratic_colour", "(b) Fig 68(a): quadratic colour function", "poor"},
  {"mass_matrix", "(c) Fig 72(a): mass matrix, per cell", "close to connectivity"},
  {"connectivity", "(d) Fig 72(b): connectivity", "the reference"},
}
local fig = lamina.figure{width = 1000, height = 1040, panels = {2, 2},
  title = "Dissertation Figs 67(a), 68(a), 72: a cylinder's normals at the first step"}
local qpts, qex = {}, {}
for k = 1, q do qpts[k], qex[k] = pts[k], ex[k] end
local arc = {}
for k = 0, 60 do
  local a = 0.5 * math.pi * k / 60
  arc[#arc + 1] = {R * math.cos(a), R * math.sin(a)}
end
local report = {}
for i, p in ipairs(panels) do
  local ns = p[1] == "connectivity" and by_connectivity() or by_method(p[1])
  local mx, med = quadrant_errors(ns)
  local qn = {}
  for k = 1, q do qn[k] = ns[k] end
  fig:panel{index = i, window = {-0.05, -0.05, 1.3, 1.3}, title = p[2],
            caption = string.format("largest error %.1f deg, median %.2f deg ([T]: %s)", mx, med, p[3])}
  fig:grid{box = {0, 0, 1.3, 1.3}, cells = {13, 13}}
  fig:polyline{points = arc, dashed = true}
  fig:arrows{at = qpts, dir = qex, length = 0.15, style = "dashed"}
  fig:arrows{at = qpts, dir = qn, length = 0.15}
  fig:points{points = qpts, style = "circle"}
  print(string.format("%-17s largest error %6.2f deg, median %6.3f deg over the %d points of the "
                      .. "first quadrant ([T]: %s)", p[1], mx, med, q, p[3]))
  report[p[1] .. "_max_error"] = {mx, unit = string.format("deg ([T]: %s)", p[3])}
  report[p[1] .. "_median_error"] = {med, unit = "deg"}
end
fig:write(out .. "/normals_variants_cylinder.png")
if lamina.report then lamina.report(report) end
