-- title: Dog-bone expansion: connectivity normals (left) against the quadratic mass matrix method (right)
-- source: York's dissertation [T] §7.7, Fig 87
-- look: the slack dog-bone membrane pushed out towards a circle twice, side
--   by side as [T] draws it: left the run whose normals come from the
--   points' connectivity, right the run whose normals come from the mass
--   matrix method with quadratic functions, cell by cell ([T] §7.7: the
--   colours on the nine cell centres; a cell holding a single point solved
--   on the four cells about it with linear functions). Each frame shows
--   the points, their normals and the phi of the construction (phi = 1
--   bold through the points). [T]: "at early times the particle positions
--   are similar ... However, at later times differences are seen in the
--   solutions. The radius of the membrane grows larger using the mass
--   matrix method as compared to using connectivity." The radii plot shows
--   both runs' r(0) and r(90)
-- checks: [T]'s two statements, as [T] words them (it prints no number):
--   the largest distance between the two runs' matching points at the
--   early frames (t = 0.05, 0.1) below that at the end (their ratio below
--   1: 0.5 +- 0.5, ours); the connectivity run's final radius below the
--   mass matrix run's (ratio below 1: 0.5 +- 0.5, ours); the radii,
--   pressures and distances printed
-- assumed: [T] does not say at which cell Fig 87 was run, nor to what
--   time: lamina's dog-bone (assets/lua/dogbone.lua, the superellipse
--   construction of normals_dynamic_dogbone) at cell 0.2 with 100 points
--   ([T] Table 5's simulation 2), 64 gas points per cell, pure FLIP, the
--   papers' point quadrature of the tension, to t = 2 (the radius settled
--   to within its oscillation); lamina's normals = "mass_matrix_quadratic":
--   each cell's mass matrix system ([T] eq 7.12, T phi = S^T phi0) solved
--   as the same least squares by the pivoted QR, because a cell with 2-8
--   points leaves the 9 x 9 T singular and [T] does not say how it solved
--   those (the elimination stopped at a zero pivot at t = 0.256: 3 rows,
--   9 unknowns); the random point from the simulation's seed
-- visual: t_end=0.2
-- thumb: fig87_t2.00.png
local out = lamina.param("out", "out/normals_mass_matrix_dogbone")
local h = lamina.param("cell", 0.2)
local t_end = lamina.param("t_end", 2)
local dog = require("dogbone")

local function build(method)
  local sim, gas, mem = dog.setup(h, { normals = method })
  local rec = sim:record{ every = 0.005, values = {
    p = function() return gas:pressure("particles") end,
    r0 = function() return mem:radius_at(0) end,
    r90 = function() return mem:radius_at(90) end } }
  return sim, rec, mem
end

local con, rec_c, mem_c = build("connectivity")
local mm, rec_m, mem_m = build("mass_matrix_quadratic")

-- the largest distance between the two runs' points of the same index
local function apart()
  local a, b = mem_c:particles(), mem_m:particles()
  local d = 0
  for i = 1, a.n do d = math.max(d, math.sqrt((a.x[i] - b.x[i])^2 + (a.y[i] - b.y[i])^2)) end
  return d
end

local early, late, t_late = 0, 0, 0
for _, tf in ipairs{0, 0.05, 0.1, 0.2, 0.4, 1, 2} do
  if tf > t_end + 1e-12 then break end
  con:run{ t_end = tf }
  mm:run{ t_end = tf }
  local d = apart()
  if tf > 0 and tf <= 0.1 + 1e-12 then early = math.max(early, d) end
  late, t_late = d, tf
  con:frame{ file = string.format("%s/fig87_t%.2f.png", out, tf), width = 720, height = 450,
             mirror = "x", split = mm, names = {"connectivity", "mass matrix (quadratic)"},
             discs = "spacing", window = {-1.6, 0, 1.6, 1.78},
             title = string.format("[T] Fig 87: t = %.2f (points %.3f apart at most)", tf, d) }
end
con:run{ t_end = t_end }
mm:run{ t_end = t_end }
if t_end > t_late + 1e-12 then late, t_late = apart(), t_end end

local tc, tm = rec_c:column("t"), rec_m:column("t")
lamina.plot{ file = out .. "/fig87_radii.png", csv = true, width = 640, height = 360,
             title = "[T] Fig 87: membrane radius at 0 and 90 degrees", xlabel = "t", ylabel = "r",
             legend = "bottom right",
             series = { { x = tc, y = rec_c:column("r0"), label = "connectivity, 0 deg" },
                        { x = tc, y = rec_c:column("r90"), label = "connectivity, 90 deg", dashed = true },
                        { x = tm, y = rec_m:column("r0"), label = "mass matrix (quadratic), 0 deg" },
                        { x = tm, y = rec_m:column("r90"), label = "mass matrix (quadratic), 90 deg",
                          dashed = true } } }

local t0 = math.max(0, t_end - 0.5)
local window = string.format("mean over t in [%.1f, %.1f]", t0, t_end)
local r_c = 0.5 * (rec_c:mean("r0", t0, t_end) + rec_c:mean("r90", t0, t_end))
local r_m = 0.5 * (rec_m:mean("r0", t0, t_end) + rec_m:mean("r90", t0, t_end))
print(string.format("points apart: early (t <= 0.1) %.4f, at t = %.2f %.4f; radius connectivity %.4f, "
  .. "mass matrix %.4f", early, t_late, late, r_c, r_m))
local fold = require("hashes").fold
lamina.report{
  early_over_late_apart = { early / late, ref = 0.5, tol = 0.5,
    unit = "([T]: similar early, differing later)" },
  connectivity_over_mass_matrix_radius = { r_c / r_m, ref = 0.5, tol = 0.5,
    unit = "([T]: larger with the mass matrix)" },
  apart_early = { early, unit = "largest distance of matching points, t = 0.05 and 0.1" },
  apart_end = { late, unit = string.format("largest distance of matching points, t = %.2f", t_late) },
  radius_connectivity = { r_c, unit = "(r(0) + r(90)) / 2, " .. window },
  radius_mass_matrix = { r_m, unit = "(r(0) + r(90)) / 2, " .. window },
  pressure_connectivity = { rec_c:mean("p", t0, t_end), unit = window },
  pressure_mass_matrix = { rec_m:mean("p", t0, t_end), unit = window },
  state_hash = fold{ con:hash(), mm:hash() },
}
