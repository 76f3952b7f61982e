-- title: An expanding cylindrical membrane run with each per-step normals method
-- source: York's dissertation [T] §7.5.2, Figs 73 and 75
-- look: Fig 73: the change of the mean radius (points at 0, 45 and 90
--   degrees) against time. With the connectivity normals (thick) the
--   cylinder expands and oscillates about its equilibrium (the black dashed
--   line; the three points' mean a little under it: the grid holds the
--   points at 0 and 90 degrees, which lie on its nodes); the mass matrix
--   method (long dashes) does the same, close to it; with the quadratic colour
--   function the membrane barely resists from the first steps and the gas
--   pushes it against the walls at x, y = 1.5 ([T]: "by t=0.005 ... virtually
--   no resistance", Fig 75(d)); the simple colour function (not in [T]'s Fig
--   73) does the same. The cubic method (thin, reddish purple: [T]'s thin
--   solid line) falls behind the quadratic run the same way (thin, sky blue)
--   from the start, holds for a moment near delta r = 0.06 (t = 0.007: [T]'s
--   "only temporarily stop it from expanding"), then goes to the walls too.
--   (The same runs at t = 0.01, [T]'s Fig 74, are the page
--   normals_cylinder_expansion_fig74.) Fig 75: positions at t = 0.05 for
--   each method (the cubic's drawn on its whole circle's first quadrant, its
--   gas points small: a clipped first point sets the disc size), (c) the cubic's
--   against the walls like (d)'s - not [T]'s Fig 75(c), where "some forces in
--   the membrane were generated to resist expansion" (the ✗ shows it)
-- checks: [T]'s "similar" as a number: the mass matrix run's mean radius
--   change over six periods (t = 0.01-0.05) within 5 % of the connectivity
--   run's (our tolerance, [F] Table IV's 5 % agreement); both against the
--   equilibrium of Laplace's law with the gas compressed adiabatically,
--   p0 (R/r)^(2 gamma) = E t ln(r/R) / ((1 - nu^2) r) (ours, closed form:
--   the engine's gas is plane strain, its membrane linear in the log strain
--   at its material's thickness; delta r 0.00899), within the same 5 %:
--   the circle's radius, every point's mean (+0.2 % and -0.9 %), and the
--   connectivity run's strain against ln(r/R) (-0.2 %). The run rings
--   undamped (period 0.0066 s, energy kept to 1e-4: no heating; the gas on
--   its adiabat to 0.14 %), so the means are over six periods. [T]'s three
--   points are printed, not checked: they read 13 % short, as this page
--   once checked them, because the radius 1.0 is a grid line and the grid
--   holds the points at 0 and 90 degrees, on the nodes (1, 0) and (0, 1),
--   where the gas ends at the cell edge (0.73 of the 45 degree point's
--   delta r; the whole circle alike, off the line at radius 1.05 none; on
--   the quadratic B-spline at cells 0.1 and 0.05 the three points and
--   every point are within 2 % of the equilibrium:
--   tests/physics/cylinder_equilibrium.lua). The linear basis' point form
--   does not converge to it: at cells 0.05 and 0.025, and at this cell past
--   t = 0.05, its radius creeps out (+16 % and +31 %; +30 % at t =
--   0.15-0.2) while its strain stays at the equilibrium's (within 1.5 %)
--   and the energy is kept, the gas's going into motion; the quadratic
--   B-spline, whose gradients do not jump at cell edges, has none: the
--   bilinear basis' cell-crossing error ([T] App. A.2;
--   scripts/measure/cylinder_equilibrium.lua). The page's window is [T]'s
--   t = 0.05, before it. The
--   quadratic run's membrane against the walls at t = 0.05 (its points
--   within a cell of x or y = 1.5: [T] Fig 75(d)). The cubic's three
--   findings, each a ratio whose side of 1 the text fixes (0.5 +- 0.5, "below
--   1", as the Figs 67-71 page; ours): "only temporarily stop": its slowest
--   1 ms of expansion (after it passed all the connectivity run reaches,
--   before half way to the walls) over the connectivity run's fastest 1 ms
--   (0.39; the quadratic run alike 1.28 and the cubic with the colour on the
--   membrane's points alone 1.98: no pause);
--   "the quadratic method is worse than the cubic": delta r at t = 0.005,
--   cubic over quadratic run alike (0.81); Fig 75(c): its delta r at t =
--   0.045-0.05 as a fraction of the way from the connectivity run's to the
--   quadratic's against the walls, between 0 and 1 (1.12: ✗, further out)
-- assumed: [T] gives no parameters for this run. The cylinder of radius 1.0
--   in quarter symmetry, walls at x, y = 1.5 (zero velocity, as [T]); the
--   normals paper's circle (assets/lua/circle_membrane.lua) scaled to it:
--   gas rho 1, p0 1000, gamma 1.4, mu 0.2, 16 ppc (clipped fill), membrane
--   rho 0.5, E 1e6, nu 0.3, t 0.1 plane stress, 181 points, point forces, cell
--   0.1, linear basis, dt 2e-5, to t = 0.05. The cubic method: its equations
--   (7.6-7.7) are lost in the text, read as the cubic B-spline on the 16
--   vertices about each point (normals = "cubic_colour", the Figs 70-71
--   page's construction). [T] ran it on the whole circle, "the boundary
--   conditions for the cubic gradient were not implemented", and so does this
--   page (no mirrored ghost points): [-1.5, 1.5]^2, fixed walls on every
--   side, 720 points (the quarter's spacing), the same gas; the colour carried
--   on the gas's points too (colour_points = gas: [T] §7.5's "with the
--   internal fluid", Figs 66(b), 70(b), 71), and a quadratic run made the
--   same way as its like-for-like comparison (Fig 73's sky-blue line; not in
--   [T]'s figure). The quarter runs' colour methods use the membrane's points
--   alone, as before
-- thumb: fig73_radius.png
local out = lamina.param("out", "out/normals_cylinder_expansion")
local t_end = lamina.param("t_end", 0.05)

local C = require("cylinder_expansion")
local R, h = C.R, C.cell
local d_eq = C.equilibrium()

-- whole: [T] ran the cubic method on the whole circle ("the boundary
-- conditions for the cubic gradient were not implemented"): the grid
-- [-1.5, 1.5]^2 with fixed walls on every side, 720 points (the quarter's
-- spacing), the colour carried on the gas's points too (colour_points:
-- [T] §7.5's "with the internal fluid", Figs 66(b), 70(b), 71). The
-- quadratic run the same way is the cubic's like-for-like comparison; the
-- cubic on the membrane's points alone shows what the gas's colour does.
local methods = {
  { key = "connectivity", label = "connectivity", width = 3 },
  { key = "mass_matrix", label = "mass matrix (linear)", dashed = true },
  { key = "quadratic_colour", label = "quadratic colour" },
  { key = "colour", label = "simple colour (not in Fig 73)", width = 1 },
  { key = "cubic_colour", label = "cubic (whole circle, gas coloured)", width = 1, color = 6,
    whole = true, gas_colour = true, fig75 = "75(c)" },
  { key = "quadratic_colour", name = "quadratic_whole", label = "quadratic (whole circle, gas coloured)",
    whole = true, gas_colour = true, width = 1, color = 5 },
  { key = "cubic_colour", name = "cubic_membrane_only", whole = true, unplotted = true,
    label = "cubic (whole circle, membrane's points only)" },
}
local curves, runs, hashes = {}, {}, {}
for _, m in ipairs(methods) do
  local name = m.name or m.key
  local sim, gas, mem = C.setup{ normals = m.key, whole = m.whole, gas_colour = m.gas_colour }
  -- [T]: "the change in the radius of material points at 0, 45, and 90 degrees are averaged"
  -- (points 1, 91 and 181 on the quarter and on the whole circle alike)
  -- and, for the equilibrium (Laplace's law is about the circle's radius), the
  -- mean over every point of the quarter (the quarter runs only: the colour
  -- methods' membranes leave the circle), its mean strain and the radius at 0
  -- and 45 degrees alone
  local vals = { dr = function() return C.dr3(mem) end }
  if not m.whole then
    vals.dr_all = function() return C.dr_all(mem) end
    vals.et_all = function() return C.strain(mem) end
    vals.dr_0 = function() local P = mem:particles(); return math.sqrt(P.x[1] ^ 2 + P.y[1] ^ 2) - R end
    vals.dr_45 = function() local P = mem:particles(); return math.sqrt(P.x[91] ^ 2 + P.y[91] ^ 2) - R end
  end
  local rec = sim:record{ every = 2.5e-4, values = vals }
  local function frame(tf, fig)
    sim:at(tf, function(s)
      s:frame{ file = string.format("%s/%s_%s_t%.3f.png", out, fig:sub(1, 2), name, tf), width = 420,
               height = 440, window = {0, 0, 1.5, 1.5}, discs = "spacing",
               title = string.format("Fig %s: %s, t = %.2f", fig, m.label:gsub(" %(.*", ""), tf) }
    end)
  end
  if not m.name then frame(t_end, m.fig75 or "75") end
  sim:run{ t_end = t_end }
  local P = mem:particles()
  local reach = 0
  for i = 1, P.n do reach = math.max(reach, math.abs(P.x[i]), math.abs(P.y[i])) end
  runs[name] = { t = rec:column("t"), dr = rec:column("dr"), rec = rec, reach = reach }
  hashes[#hashes + 1] = sim:hash()
  if not m.unplotted then
    curves[#curves + 1] = { x = runs[name].t, y = runs[name].dr, label = m.label, dashed = m.dashed,
                            width = m.width, color = m.color }
  end
end
curves[#curves + 1] = { x = {0, t_end}, y = {d_eq, d_eq}, dashed = true, color = 8,
                        label = "equilibrium (Laplace, adiabatic gas; ours)" }
lamina.plot{ file = out .. "/fig73_radius.png", csv = true, width = 760, height = 440,
             title = "Fig 73: change of the mean radius (points at 0, 45, 90 deg)", xlabel = "t",
             ylabel = "delta r", legend = "best", yrange = {-0.02, 0.68}, series = curves }

local t0 = math.min(0.01, 0.2 * t_end)
local conn = runs.connectivity.rec:mean("dr", t0, t_end)
local mm = runs.mass_matrix.rec:mean("dr", t0, t_end)
-- The equilibrium is that of the circle: its radius is the mean over every
-- point. [T]'s three points are no estimate of it on this grid: the radius
-- 1.0 is a grid line, so the points at 0 and 90 degrees sit on the nodes
-- (1, 0) and (0, 1), where the gas ends at the cell edge, and the grid holds
-- them back (over t = 0.01-0.05 they move out 0.0070, the point at 45
-- degrees 0.0095; the whole circle alike, so not the symmetry walls;
-- scripts/measure/cylinder_equilibrium.lua)
local conn_all = runs.connectivity.rec:mean("dr_all", t0, t_end)
local mm_all = runs.mass_matrix.rec:mean("dr_all", t0, t_end)
local conn_et = runs.connectivity.rec:mean("et_all", t0, t_end)
local lag = runs.connectivity.rec:mean("dr_0", t0, t_end) / runs.connectivity.rec:mean("dr_45", t0, t_end)
local apart = 0
for i = 1, #runs.connectivity.dr do
  apart = math.max(apart, math.abs(runs.connectivity.dr[i] - runs.mass_matrix.dr[i]))
end
print(string.format("equilibrium delta r %.5f; mean over t = %g-%g, [T]'s 3 points: connectivity %.5f, "
  .. "mass matrix %.5f; every point: connectivity %.5f, mass matrix %.5f (strain %.5f, ln(1 + delta r) %.5f; "
  .. "0 deg over 45 deg %.3f); largest distance between them %.5f; reach at the end: quadratic %.3f, colour %.3f",
  d_eq, t0, t_end, conn, mm, conn_all, mm_all, conn_et, math.log(1 + d_eq), lag, apart,
  runs.quadratic_colour.reach, runs.colour.reach))

-- [T] on the cubic method (Fig 73's thin solid line), three findings as
-- numbers (each a ratio whose sign the text fixes: 0.5 +- 0.5 is "below 1",
-- as on the Figs 67-71 page; ours):
-- (1) "the forces in the membrane only temporarily stop it from
-- expanding": a pause - for 1 ms the radius grows no faster than the
-- connectivity membrane, which resists, ever moves (its largest change of
-- delta r in 1 ms, the pace of its oscillation) - taken after the cubic
-- run has passed everything the connectivity run reaches and before it is
-- half way to the walls (delta r 0.25), so that it expands again after it
local function pause_of(run)
  local cmax, pace = 0, 0
  local cd = runs.connectivity.dr
  for i = 1, #cd do cmax = math.max(cmax, cd[i]) end
  for i = 1, #cd - 4 do pace = math.max(pace, math.abs(cd[i + 4] - cd[i])) end
  local slow, at_t = math.huge, nil
  for i = 1, #run.dr - 4 do
    if run.dr[i] > cmax and run.dr[i + 4] < 0.25 and run.dr[i + 4] - run.dr[i] < slow then
      slow, at_t = run.dr[i + 4] - run.dr[i], run.t[i]
    end
  end
  return slow / pace, at_t, pace
end
local function dr_at(run, t) return run.rec:mean("dr", t - 5e-4, t + 5e-4) end
local function dr_end(run) return run.rec:mean("dr", t_end - 5e-3, t_end) end
local cub, qw, cmo = runs.cubic_colour, runs.quadratic_whole, runs.cubic_membrane_only
local pause, pause_t, pace = pause_of(cub)
local pause_mo, pause_qw = pause_of(cmo), pause_of(qw)
-- (2) "The quadratic method is worse than the cubic method. By t=0.005
-- ... virtually no resistance": the cubic's delta r at t = 0.005 over the
-- quadratic's, run the same way (whole circle, gas coloured)
local c_q = dr_at(cub, 0.005) / dr_at(qw, 0.005)
-- (3) Fig 75(c): "some forces in the membrane were generated to resist
-- expansion", against (d) the quadratic's membrane "pushed against the
-- boundaries": at t = 0.05 the cubic's delta r between the successful
-- runs' (connectivity) and the quadratic's (Fig 75(d)'s run), as a
-- fraction of the way from one to the other (mean over t = 0.045-0.05)
local c_end, q_end, k_end = dr_end(cub), dr_end(runs.quadratic_colour), dr_end(runs.connectivity)
local between = (c_end - k_end) / (q_end - k_end)
print(string.format("cubic (whole circle, gas coloured): slowest 1 ms %.4f of the connectivity run's pace %.4f "
  .. "(at t = %.4f); membrane's points only: %.3f; the quadratic alike: %.3f; delta r at t = 0.005: cubic %.4f, quadratic (whole) %.4f, "
  .. "quadratic (quarter) %.4f, cubic (membrane only) %.4f; at the end: cubic %.4f, quadratic %.4f "
  .. "(whole %.4f), connectivity %.4f; reach: cubic %.3f",
  pause * pace, pace, pause_t or -1, pause_mo, pause_qw, dr_at(cub, 0.005), dr_at(qw, 0.005),
  dr_at(runs.quadratic_colour, 0.005), dr_at(cmo, 0.005), c_end, q_end, dr_end(qw), k_end, cub.reach))
local h64 = 0xcbf29ce484222325
for _, c in ipairs(hashes) do for i = 1, #c do h64 = (h64 ~ c:byte(i)) * 0x100000001b3 end end
lamina.report{
  mass_matrix_vs_connectivity_mean = { 100 * (mm - conn) / conn, ref = 0, tol = 5,
                                        unit = "% (mean delta r, t = 0.01-0.05; [T]: similar)" },
  connectivity_mean_dr = { conn_all, ref = d_eq, tol = 0.05 * d_eq,
                           unit = "(every point's delta r, t = 0.01-0.05; equilibrium, ours; tol [F] Table IV's 5 %)" },
  mass_matrix_mean_dr = { mm_all, ref = d_eq, tol = 0.05 * d_eq,
                          unit = "(every point's delta r, t = 0.01-0.05; equilibrium, ours; tol [F] Table IV's 5 %)" },
  connectivity_mean_strain = { conn_et, ref = math.log(1 + d_eq), tol = 0.05 * math.log(1 + d_eq),
                               unit = "(every point's strain, t = 0.01-0.05; ln(r/R) at the equilibrium, ours; "
                                      .. "tol [F] Table IV's 5 %)" },
  connectivity_3pt_dr = { conn, unit = "([T]'s 3 points, t = 0.01-0.05: "
                                       .. string.format("%.2f", conn / d_eq) .. " of the equilibrium; "
                                       .. "the points at 0 and 90 deg held on the grid's nodes)" },
  mass_matrix_3pt_dr = { mm, unit = "([T]'s 3 points, t = 0.01-0.05: "
                                    .. string.format("%.2f", mm / d_eq) .. " of the equilibrium)" },
  connectivity_0_over_45 = { lag, unit = "(delta r at 0 deg over 45 deg, t = 0.01-0.05: the grid holds the first)" },
  mass_matrix_vs_connectivity_max = { apart, unit = "largest |delta r| difference ([T]: similar)" },
  quadratic_reach = { runs.quadratic_colour.reach, ref = 1.5, tol = h,
                      unit = "largest x or y of its points at the end (walls at 1.5; [T] Fig 75(d))" },
  quadratic_dr_0_005 = { runs.quadratic_colour.rec:mean("dr", 0.0045, 0.0055) / d_eq,
                         unit = "x the equilibrium at t = 0.005 ([T]: virtually no resistance)" },
  colour_reach = { runs.colour.reach, unit = "(walls at 1.5)" },
  cubic_pause = { pause, ref = 0.5, tol = 0.5,
                  unit = "(slowest 1 ms of its expansion over the connectivity run's fastest; [T] Fig 73: "
                         .. "'only temporarily stop it': below 1)" },
  cubic_pause_membrane_only = { pause_mo, unit = "(the same, the colour on the membrane's points alone)" },
  quadratic_whole_pause = { pause_qw, unit = "(the same for the quadratic run alike: whole circle, gas coloured)" },
  cubic_over_quadratic_0_005 = { c_q, ref = 0.5, tol = 0.5,
                                 unit = "(delta r at t = 0.005, both whole circle, gas coloured; [T]: "
                                        .. "'the quadratic method is worse than the cubic': below 1)" },
  cubic_between_t_end = { between, ref = 0.5, tol = 0.5,
                          unit = "(delta r at t = 0.045-0.05: 0 connectivity's, 1 the quadratic's against "
                                 .. "the walls; [T] Fig 75(c) 'some forces ... to resist': between)" },
  cubic_reach = { cub.reach, unit = "largest |x| or |y| of its points at the end (walls at 1.5)" },
  state_hash = string.format("%016x", h64),
}
