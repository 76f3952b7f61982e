-- lamina.normals and lamina.figure beyond the static cases: bad input gives clear errors
-- (issue 4 item 7: too few points, coincident points, points outside the element; never a NaN
-- normal), grids with the hybrid rule and merging, orientation, the dissertation's variants,
-- and a figure written to PNG.
local function fails(args, pattern)
  local ok, err = pcall(lamina.normals, args)
  assert(not ok, "expected an error matching '" .. pattern .. "'")
  assert(tostring(err):find(pattern, 1, true), "error '" .. tostring(err) .. "' lacks '" ..
         pattern .. "'")
end

local box = {0, 0, 1, 1}
local line = {{0.2, 0.2}, {0.5, 0.5}, {0.8, 0.8}}
fails({points = line, box = box, bogus = 1}, "unknown key 'bogus'")
fails({points = line}, "'box' is required")
fails({points = line, box = {0, 0, 1}}, "'box' must be")
fails({points = line, box = {0, 0, 0, 1}}, "'box' is empty")
fails({points = {}, box = box}, "no membrane points")
fails({points = {{0.2, 0.2}, {1.5, 0.5}}, box = box}, "point 2 (1.5, 0.5) lies outside the element")
fails({points = {{0.2, 0.2}, {0.3}}, box = box}, "points[2] must be {x, y}")
fails({points = {{0.2, 0.2}, {0.3, 0 / 0}}, box = box}, "point 2")
fails({points = {{0.4, 0.4}, {0.4, 0.4}, {0.4, 0.4}}, box = box},
      "only 1 distinct membrane point")
fails({points = line, box = box, basis = "cubic"}, "basis = \"cubic\" is not one of")
fails({points = line, box = box, basis = "hybrid"}, "needs 'cells'")
fails({points = line, box = box, seed = 1, random_point = {0.1, 0.9}}, "not both")
fails({points = line, box = box, seed = -1}, "'seed' must be a whole number")
fails({points = line, box = box, cells = {2, 2}, random_point = {0.1, 0.9}}, "every element")
fails({points = line, box = box, method = "colour", basis = "linear"}, "does not apply")
fails({points = {{0.3, 0.3}}, box = box, cells = {2, 2}}, "whole grid")

-- coincident points: accepted, reported, finite normals
local r = lamina.normals{points = {{0.2, 0.2}, {0.2, 0.2}, {0.5, 0.5}, {0.8, 0.8}}, box = box}
assert(r.coincident and r.unique == 3 and r.points == 4)
for _, n in ipairs(r.normals) do assert(n[1] == n[1] and math.abs(n[1] + n[2]) < 1e-10) end

-- an undefined normal is an error naming the point, never a zero or NaN vector: here a cell
-- holds points only on its left edge x = 0, where phi - 1 = x (a + b y) leaves grad phi = 0 at
-- one of them (found among degenerate sets, see tests/unit/test_normals_grid.c)
local edge = {{0, 2}, {2, 0}, {1, 0}, {2, 2}, {0, 2}, {2, 2.5}, {2, 1.5}, {1, 2}, {0, 2.5},
              {2, 2.5}, {0, 1}}
fails({points = edge, box = {0, 0, 3, 3}, cells = {3, 3}, basis = "linear", seed = 23},
      "the normal at point 1 (0, 2) is undefined")

-- orientation: away from a point, for every point
local arc = {}
for k = 0, 8 do
  local t = math.rad(190 + 10 * k)
  arc[#arc + 1] = {0.5 + 0.3 * math.cos(t), 0.5 + 0.3 * math.sin(t)}
end
for _, seed in ipairs({1, 2, 3, 4}) do
  local o = lamina.normals{points = arc, box = box, basis = "quadratic", seed = seed,
                           orient = {0.5, 0.5}}
  for k, n in ipairs(o.normals) do
    assert(n[1] * (arc[k][1] - 0.5) + n[2] * (arc[k][2] - 0.5) > 0, "orient = point")
  end
end

-- a grid: the quarter circle of [N] Fig 12 (static), hybrid rule, merged ends
local circle = {}
for k = 0, 90 do
  local t = 0.5 * math.pi * k / 90
  circle[#circle + 1] = {0.5 * math.cos(t), 0.5 * math.sin(t)}
end
local g = lamina.normals{points = circle, box = {0, 0, 1, 1}, cells = {10, 10}, orient = {0, 0}}
assert(#g.normals == 91 and #g.elements == 9, "9 occupied cells")
local merged, quadratic = 0, 0
for _, e in ipairs(g.elements) do
  if e.merged then merged = merged + 1 end
  if e.basis == "quadratic" then quadratic = quadratic + 1 end
end
assert(merged == 2 and quadratic == 7, "the ends merge, the rest is quadratic")
local worst = 0
for k = 4, 88 do
  local n, p = g.normals[k], circle[k]
  worst = math.max(worst, math.abs(n[1] * p[2] - n[2] * p[1]) / 0.5)
  assert(n[1] * p[1] + n[2] * p[2] > 0, "outward")
end
assert(worst < 1e-8, "away from the ends the hybrid normals are exact: " .. worst)
assert(math.abs(g.phi_at(circle[40][1], circle[40][2]) - 1) < 1e-10, "phi_at on a grid")
assert(g.phi_at(0.95, 0.95) == nil, "no element there")

-- the dissertation's variants run and give unit normals
for _, m in ipairs({"colour", "quadratic_colour", "mass_matrix", "mass_matrix_global"}) do
  local v = lamina.normals{points = circle, box = {0, 0, 1, 1}, cells = {10, 10}, method = m}
  assert(#v.normals == 91)
  for _, n in ipairs(v.normals) do assert(math.abs(n[1] ^ 2 + n[2] ^ 2 - 1) < 1e-12, m) end
end

-- a figure: every layer once, written with provenance
local fig = lamina.figure{width = 400, height = 300, panels = {2, 1}, title = "api test"}
assert(tostring(fig):find("lamina.figure", 1, true))
local okp, perr = pcall(fig.points, fig, {points = line})
assert(not okp and perr:find("no window yet", 1, true), "a panel needs a window first")
fig:panel{index = 1, window = {-0.1, -0.1, 1.1, 1.1}, title = "(a)", caption = "first"}
local single = lamina.normals{points = line, box = box, seed = 2, orient = {1, 0}}
fig:normals{result = single, points = line,
            exact = {{-0.7071, 0.7071}, {-0.7071, 0.7071}, {-0.7071, 0.7071}}}
fig:contours{phi = function(x, y) return x + y end, levels = {0.5, 1, 1.5}}
fig:grid{box = {0, 0, 1, 1}, cells = {4, 4}}
fig:polyline{points = line, dashed = true}
fig:text{text = "label", at = {0.1, 0.9}}
fig:caption{text = "second line"}
fig:panel{index = 2, box = {0, 0, 0, 1, 1, 1}, azimuth = -50, elevation = 20}
fig:outline{}
fig:points{points = {{0.5, 0.5, 0.5}}, style = "asterisk"}
fig:arrows{at = {{0.5, 0.5, 0.5}}, dir = {{0, 0, 1}}, style = "dashed"}
local bad = pcall(fig.arrows, fig, {at = {{0.5, 0.5, 0.5}}, dir = {{0, 0, 1}}, sytle = "x"})
assert(not bad, "unknown keys are rejected by the figure too")
local file = fig:write("normals_api_figure.png")
assert(file == "normals_api_figure.png")
