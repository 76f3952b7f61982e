-- title: Normals in three dimensions with the triquadratic basis: plane and sphere exact (normals paper Fig 11)
-- source: normals paper Fig 11 (a-b) ([N] §6): 27 x 27 systems on the unit cube
-- look: (a) 30 points on the plane 0.5x + 0.25y - z = 0, (b) 29 points on the sphere
--       x^2 + y^2 + z^2 = 0.8^2; in both the computed normals (solid) hide the exact ones (dashed).
--       The 3D views are drawn by OpenGL through OSMesa when lamina has it (depth-tested:
--       points as spheres, arrow heads as cones, what is behind hidden), else as cairo's
--       projection from the same camera.
-- checks: both exact to round-off (paper: "The normals are computed exactly in both cases"); the
--         rank of each system: the sphere's 29 points determine all 27 unknowns, while any points
--         on a plane leave 8 free (the plane times any multilinear function vanishes there), so
--         (a) is solved by the minimum-norm QR solution - exact in direction all the same.
-- assumed: the points are not given in the paper. (a) a 5 x 6 grid, x = (i + 1/2)/5,
--          y = (j + 1/2)/6; (b) a Fibonacci spiral on the octant as in normals_fig5.lua.
local nu = require("normals_util")
local angle, sphere_points, plane_outline = nu.angle, nu.sphere_points, nu.plane_outline
local out = lamina.param("out", "out/normals_fig11")
local seed = lamina.param("seed", 1)

local function max_error(ns, ex)
  local m = 0
  for k = 1, #ns do m = math.max(m, angle(ns[k], ex[k])) end
  return m
end

local function plane_points()
  local pts, ex = {}, {}
  local l = math.sqrt(0.25 + 0.0625 + 1)
  for i = 0, 4 do
    for j = 0, 5 do
      local x, y = (i + 0.5) / 5, (j + 0.5) / 6
      pts[#pts + 1], ex[#ex + 1] = {x, y, 0.5 * x + 0.25 * y}, {-0.5 / l, -0.25 / l, 1 / l}
    end
  end
  return pts, ex
end

local function sphere_outline(fig)
  for axis = 1, 3 do
    local arc = {}
    for k = 0, 30 do
      local t = 0.5 * math.pi * k / 30
      local p = {0, 0, 0}
      p[axis % 3 + 1], p[(axis + 1) % 3 + 1] = 0.8 * math.cos(t), 0.8 * math.sin(t)
      arc[#arc + 1] = p
    end
    fig:polyline{points = arc, dashed = true}
  end
end

local cube = {0, 0, 0, 1, 1, 1}
local fig = lamina.figure{width = 1000, height = 560, panels = {2, 1},
  title = "Normals paper Fig 11: quadratic (27 x 27) construction in 3D"}
local cases = {
  {pts = {plane_points()}, label = "(a) 30 points on 0.5x + 0.25y - z = 0", orient = {0.5, 0.5, 0},
   outline = plane_outline},
  {pts = {sphere_points(29, 0.8)}, label = "(b) 29 points on x^2 + y^2 + z^2 = 0.8^2",
   orient = {0, 0, 0}, outline = sphere_outline},
}
local worst = 0
for i, c in ipairs(cases) do
  local pts, ex = c.pts[1], c.pts[2]
  local r = lamina.normals{points = pts, box = cube, basis = "quadratic", seed = seed,
                           orient = c.orient}
  local m = max_error(r.normals, ex)
  local w = 0
  for t = 1, 100 do
    w = math.max(w, max_error(lamina.normals{points = pts, box = cube, basis = "quadratic",
                                             seed = t}.normals, ex))
  end
  worst = math.max(worst, w)
  -- axis names beside the cube's outline: at the far ends of the axes the
  -- y name falls inside the cube, among the points (docs/gallery.md,
  -- "Legibility checklist" 5)
  fig:panel{index = i, box = cube, title = c.label, axes = "outside",
            caption = string.format("max error %.1e rad (paper: exact); rank %d of 27", m, r.rank)}
  c.outline(fig)
  fig:normals{result = r, points = pts, exact = ex, length = 0.22}
  print(string.format("Fig 11%s: max error %.2e rad (paper: exact), rank %d of %d, cond(T) %.3g; "
    .. "worst of 100 random points %.2e rad", c.label:sub(1, 3), m, r.rank, r.unknowns, r.cond, w))
end
fig:write(out .. "/normals_fig11.png")
if lamina.report then
  lamina.report{ fig11_worst_error = {worst, paper = 0, unit = "rad", tol = 1e-8} }
end
