-- title: Dog-bone expansion at cell 0.05: positions with pressure contours, and the membrane's stress
-- source: York, Sulsky & Schreyer 2000 (fluid-membrane), §4.3.2, Fig 12; York's dissertation §6.2.4, Fig 56
-- look: [F] Fig 12: the material points at increasing times over the gas
--   pressure interpolated to the nodes (one colour range for every frame),
--   the last (t = 4) larger: the slack membrane is pushed out, rings and
--   settles to a smooth quarter circle, the pressure nearly uniform inside.
--   [T] Fig 56: the same at t = 4 beside the membrane drawn as a band
--   coloured by its tangential stress sigma_t
-- checks: at cell 0.05 (simulation 4) the space-mean pressure and the radii at
--   0 and 90 degrees over t = 3-4 beside [T] Table 5's 29.0, 1.394 and
--   1.396, within the two papers' own difference at that cell ([F] Table III:
--   31.7 and 1.36); Laplace's law, the mean tangential stress against p r / t
--   of the same run (ours) within [F] Table IV's 5 %; gas outside the membrane
-- assumed: gas_dogbone_bspline's set-up (its header: lamina's superellipse
--   dog-bone, assets/lua/dogbone.lua; gas rho 1, mu 0.2, e 250, 64 ppc;
--   membrane rho 0.5, E 1e6, nu 0.3, t 0.1, plane stress, one-way, 400
--   points, point forces) on the quadratic B-spline: the papers' bilinear
--   basis fails at this cell without gas splitting (gas_dogbone_superellipse);
--   two threads. The pressure bands are the nodal pressure without q
--   (sim:frame contours, [T]: "interpolated to grid points from material points")
-- heavy: cell 0.05 to t = 4 with the quadratic B-spline: about 4 min here on two threads
-- visual: cell=0.2 t_end=0.3 threads=1
-- thumb: fig12_t4.0.png
local out = lamina.param("out", "out/gas_dogbone_contours_fine")
local h = lamina.param("cell", 0.05)
local t_end = lamina.param("t_end", 4)
local threads = lamina.param("threads", 2)
local dog = require("dogbone")

local sim, gas, mem = dog.setup(h, { basis = "bspline2", force = "point", threads = threads })
local escaped = 0
local rec = sim:record{ every = 0.01, file = out .. "/history.csv", values = {
  p = function() return gas:pressure(mem) end,
  hoop = function() return mem:hoop_stress() end,
  r0 = function() return mem:radius_at(0) end,
  r90 = function() return mem:radius_at(90) end,
  escaped = function()
    local beyond, _, grazing = mem:escaped(gas)
    escaped = math.max(escaped, beyond + grazing)
    return escaped end } }
local p_range, window = {0, 80}, {0, 0, 1.55, 1.55}
for _, tf in ipairs{0, 0.2, 0.5, 1, 2} do
  if tf < t_end then
    sim:at(tf, function(s)
      s:frame{ file = string.format("%s/fig12_t%.1f.png", out, tf), width = 360, height = 380,
               window = window, title = string.format("Fig 12: cell %.2f, t = %.1f", h, tf),
               contours = "pressure", particles = "membranes", grid = false, range = p_range,
               contour_levels = 16 }
    end)
  end
end
sim:at(t_end, function(s)
  s:frame{ file = string.format("%s/fig12_t%.1f.png", out, t_end), width = 640, height = 640,
           window = window, title = string.format("Fig 12: cell %.2f, t = %.1f", h, t_end),
           contours = "pressure", particles = "membranes", grid = false, range = p_range,
           contour_levels = 16 }
  s:frame{ file = string.format("%s/fig56_t%.1f.png", out, t_end), width = 800, height = 440,
           layout = {1, 2}, window = window, title = string.format("Fig 56: cell %.2f, t = %.1f", h, t_end),
           panels = {
             { title = "gas pressure at the nodes", contours = "pressure", particles = "membranes",
               grid = false, range = p_range, contour_levels = 16 },
             { title = "membrane stress sigma_t", colour = "membrane_stress", colourmap = "viridis",
               particles = "membranes", grid = false, range = {0, 1000}, band = 7 } } }
end)
local clock = lamina.clock()
sim:run{ t_end = t_end }
local secs = lamina.clock() - clock
local t0 = math.max(0, t_end - 1)
local p, hoop = rec:mean("p", t0, t_end), rec:mean("hoop", t0, t_end)
local r0, r90 = rec:mean("r0", t0, t_end), rec:mean("r90", t0, t_end)
local prt = p * 0.5 * (r0 + r90) / 0.1
print(string.format("cell %.3f: %d steps in %.0f s; over t = %g-%g r(0) %.4f r(90) %.4f p %.2f, "
  .. "hoop %.1f against p r / t %.1f (%+.2f %%); gas outside %d", h, sim.nstep, secs, t0, t_end,
  r0, r90, p, hoop, prt, 100 * (hoop - prt) / prt, escaped))
-- [T] Table 5 (simulation 4) with [F] Table III's difference as the tolerance,
-- as gas_dogbone_bspline; only at the papers' cell
local fine = math.abs(h - 0.05) < 1e-9
lamina.report{
  pressure = fine and { p, paper = 29.0, tol = 2.7, unit = "([T] Table 5; tol: [F] Table III's 31.7)" } or p,
  radius_0 = fine and { r0, paper = 1.394, tol = 0.034, unit = "([T] Table 5; tol: [F] Table III's 1.36)" } or r0,
  radius_90 = fine and { r90, paper = 1.396, tol = 0.036, unit = "([T] Table 5; tol: [F] Table III's 1.36)" } or r90,
  hoop_vs_prt = { 100 * (hoop - prt) / prt, ref = 0, tol = 5,
                  unit = "% (against p r / t of this run, ours; [F] Table IV's 5 %)" },
  gas_outside = escaped,
  seconds = { secs, unit = string.format("s (%d thread%s)", threads, threads == 1 and "" or "s") },
  state_hash = sim:hash(),
}
