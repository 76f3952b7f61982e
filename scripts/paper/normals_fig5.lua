-- title: Normals in three dimensions with the trilinear basis: a plane and a sphere (normals paper Fig 5)
-- source: normals paper Fig 5 (a-b) ([N] §4, "Three Dimensions"): 8 x 8 systems on the unit cube
-- look: (a) nine points on the plane 0.5x + 0.25y - z = 0, the computed normals (solid) on top of
--       the exact ones (dashed), all parallel; (b) eight points on the sphere x^2 + y^2 + z^2 = 0.8^2
--       in the cube's corner octant, computed normals leaning a few degrees off the radial
--       (dashed) ones. The 3D views are drawn by OpenGL through OSMesa when lamina has it
--       (depth-tested: points as spheres, arrow heads as cones, what is behind hidden), else
--       as cairo's projection from the same camera.
-- checks: (a) exact to round-off; (b) max and rms angle error (paper: max 13 degrees, rms 3
--         degrees; the paper's rms is sqrt(sum e^2)/n, see normals_fig4.lua, printed beside the
--         usual rms), each within half a degree (the printed precision: [N] states no
--         agreement; it was half the value).
-- assumed: the points are not given in the paper. (a) a 3 x 3 grid x, y in {0.2, 0.5, 0.8};
--          (b) a Fibonacci spiral on the octant: cos(polar angle) = (k + 1/2)/8, azimuth
--          90 deg x frac(k (3 - sqrt 5)/2 ... golden angle), k = 0..7.
local nu = require("normals_util")
local angle, errors, sphere_points, plane_outline = nu.angle, nu.errors, nu.sphere_points, nu.plane_outline
local out = lamina.param("out", "out/normals_fig5")
local seed = lamina.param("seed", 1)

local function plane_points()
  local pts, ex = {}, {}
  local l = math.sqrt(0.25 + 0.0625 + 1)
  for i = 0, 2 do
    for j = 0, 2 do
      local x, y = 0.2 + 0.3 * i, 0.2 + 0.3 * j
      pts[#pts + 1], ex[#ex + 1] = {x, y, 0.5 * x + 0.25 * y}, {-0.5 / l, -0.25 / l, 1 / l}
    end
  end
  return pts, ex
end

local function sphere_outline(fig, r)
  for axis = 1, 3 do
    local arc = {}
    for k = 0, 30 do
      local t = 0.5 * math.pi * k / 30
      local p = {0, 0, 0}
      p[axis % 3 + 1], p[(axis + 1) % 3 + 1] = r * math.cos(t), r * math.sin(t)
      arc[#arc + 1] = p
    end
    fig:polyline{points = arc, dashed = true}
  end
end

local fig = lamina.figure{width = 1000, height = 560, panels = {2, 1},
  title = "Normals paper Fig 5: linear (8 x 8) construction in 3D"}
local cube = {0, 0, 0, 1, 1, 1}

local pa, ea = plane_points()
local ra = lamina.normals{points = pa, box = cube, basis = "linear", seed = seed,
                          orient = {0.5, 0.5, 0}}
local ma = errors(ra.normals, ea)
fig:panel{index = 1, box = cube, axes = "outside", title = "(a) 9 points on 0.5x + 0.25y - z = 0",
          caption = string.format("max error %.1e rad (paper: exact), cond(T) %.2g", ma, ra.cond)}
plane_outline(fig)
fig:normals{result = ra, points = pa, exact = ea, length = 0.25}
print(string.format("Fig 5(a): max error %.2e rad (paper: exact), cond(T) %.3g", ma, ra.cond))

local pb, eb = sphere_points(8, 0.8)
local rb = lamina.normals{points = pb, box = cube, basis = "linear", seed = seed,
                          orient = {0, 0, 0}}
local mb, rmsb, altb = errors(rb.normals, eb)
fig:panel{index = 2, box = cube, axes = "outside", title = "(b) 8 points on x^2 + y^2 + z^2 = 0.8^2",
          caption = string.format("max %.1f deg, rms %.1f deg, sqrt(sum e^2)/n %.1f deg "
            .. "(paper 13, 3)", math.deg(mb), math.deg(rmsb), math.deg(altb))}
sphere_outline(fig, 0.8)
fig:normals{result = rb, points = pb, exact = eb, length = 0.25}
fig:write(out .. "/normals_fig5.png")
print(string.format("Fig 5(b): max %.2f deg, rms %.2f deg, sqrt(sum e^2)/n %.2f deg "
  .. "(paper: max 13 deg, rms 3 deg), cond(T) %.3g", math.deg(mb), math.deg(rmsb),
  math.deg(altb), rb.cond))

-- the same over 100 random points
local worst, sum = 0, 0
for t = 1, 100 do
  local r = lamina.normals{points = pb, box = cube, basis = "linear", seed = t}
  local m = errors(r.normals, eb)
  worst, sum = math.max(worst, m), sum + m
end
print(string.format("Fig 5(b), 100 random points: max error mean %.2f deg, worst %.2f deg",
  math.deg(sum / 100), math.deg(worst)))
if lamina.report then
  lamina.report{ fig5a_max_error = {ma, paper = 0, unit = "rad", tol = 1e-10},
                 -- [N] prints whole degrees and no agreement: half a degree, its precision
                 -- (issue 32: was half the value)
                 fig5b_max_error = {math.deg(mb), paper = 13, tol = 0.5, unit = "deg (tol: half the printed degree)"},
                 fig5b_rms_paper_style = {math.deg(altb), paper = 3, tol = 0.5,
                                          unit = "deg, sqrt(sum e^2) / n as [N]'s Table III fits (tol: half the printed degree)"},
                 fig5b_rms_usual = {math.deg(rmsb), unit = "deg, sqrt(sum e^2 / n): the usual rms"} }
end
