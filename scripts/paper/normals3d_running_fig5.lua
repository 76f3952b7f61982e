-- title: Normals of a running sphere from the trilinear construction (normals paper Fig 5, in a 3D simulation)
-- source: normals paper Fig 5 ([N] §4, "Three Dimensions": the 8 x 8 trilinear system), made
--   every few steps on the points of a membrane sphere running in lamina's 3D MPM
-- look: the sphere's points (blue), the trilinear construction's phi = 1 surface (see-through
--   green, element by element) and its normals (red). Where the points of an element lie on
--   a nearly flat patch the trilinear phi = 1 does not: it bends and folds inside the cube
--   (green fins standing off the sphere in the close-up), and the normals taken from it
--   lean far from radial - most points' arrows are close to radial, a few hundred are not,
--   some lying almost in the sphere's tangent plane. The same run's triquadratic
--   construction is normals3d_running_fig11 (every normal within 0.07 degrees)
-- checks: the construction's normals against the radial direction from the centre, the
--   worst over every point of every sample, held to issue 34 item 3's 2 degrees: an
--   EXPECTED FAILURE (x), measured 78-87 degrees at worst, 289-296 of 4072 points beyond 2
--   degrees at every sample, the rms 3.7-4.7 degrees - the trilinear fit's phi = 1 in a cell
--   is a curved surface (a trilinear function's level set) even where its points are flat,
--   as [N] Fig 7 shows in 2D (and [N] Fig 5 (b) itself: 13 degrees on 8 points of a sphere);
--   the sphere itself against Laplace's law (strain and tension, as the Fig 11 page)
-- assumed: the paper's Fig 5 is static (8 points of a sphere on one unit cube); here
--   the points are the 4072 of a Fibonacci sphere r0 = 0.3 at spacing h/3 on the running
--   quadratic B-spline grid (h = 0.05), under p = 100 Pa, damped (200 1/s) - the balloon
--   of test_sim3_membrane and physics.sim3_membrane (assets/lua/running_sphere3.lua). The
--   membrane steps with its connectivity normals (t1 x t2), so the construction is measured,
--   not fed back; the elements are lamina's centred ones (one cell about the half-cell
--   lattice site nearest each point, with its curvature rows and random-point clearance,
--   docs/normals.md "Centred elements"), not the paper's per-cell ones
-- visual: steps=50
-- thumb: sphere_t0.1500.png
local rs = require("running_sphere3")
local out = lamina.param("out", "out/normals3d_running_fig5")
local steps = lamina.param("steps", 300)
local every = 25

local sim, m = rs.setup()
local function shot(t, k)
  local cap, wl = rs.closeup(m)
  sim:frame{ file = string.format("%s/sphere_t%.4f.png", out, t), width = 1000, height = 500,
             title = string.format("Fig 5 on a running sphere: trilinear phi = 1 and normals, t = %.4f s", t),
             normals = "linear", phi = "linear", layout = {1, 2},
             panels = { { title = "whole sphere", radius = 1.5, box = {0.15, 0.15, 0.15, 0.85, 0.85, 0.85} },
                        { title = string.format("close-up where the trilinear normal is worst (%.0f deg)", wl), target = cap.target, distance = cap.distance,
                          azimuth = cap.azimuth, elevation = cap.elevation, outline = false } } }
end
local s = rs.run(sim, m, steps, every, {0, steps}, shot)

local two = {}
for i = 1, #s.t do two[i] = 2 end
lamina.plot{ file = out .. "/angles.png", title = "Trilinear construction ([N] Fig 5) on the running sphere",
             xlabel = "t (s)", ylabel = "angle to radial (deg)", csv = true, legend = "best",
             yrange = {0, 95},
             series = { { x = s.t, y = s.linear_worst, label = "worst point", markers = true },
                        { x = s.t, y = s.linear_rms, label = "rms over the points", markers = true },
                        { x = s.t, y = two, label = "issue 34: 2 deg", dashed = true, color = 8 } } }

local rm, Tm = rs.state(m)
local req = rs.laplace_radius()
lamina.report{
  -- ours: a sphere's normal is radial; tol issue 34 item 3's 2 degrees
  -- an expected failure: the trilinear phi = 1 bends where the points are
  -- flat ([N] Fig 7 in 2D); measured 78-87 degrees
  normals_worst = { rs.max(s.linear_worst), ref = 0, tol = 2, unit = "deg" },
  normals_rms_largest = { rs.max(s.linear_rms), unit = "deg" },
  points_beyond_2deg = rs.max(s.linear_beyond),
  triquadratic_worst = { rs.max(s.quadratic_worst), unit = "deg (the same points, Fig 11's construction)" },
  normals_undefined = s.undefined,
  -- ours: Laplace's radius; T = E t ln(r/r0) / (1 - nu), so issue 34's 2 % on
  -- the tension is 2 % on the strain ln(r/r0)
  strain_over_laplace = { math.log(rm / rs.r0) / math.log(req / rs.r0), ref = 1, tol = 0.02 },
  tension_over_pr2 = { Tm / (rs.p * rm / 2), ref = 1, tol = 0.02 },
  points = #m,
  steps = sim.nstep,
  state_hash = sim:hash(),
}
