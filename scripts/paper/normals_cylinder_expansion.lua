-- title: An expanding cylindrical membrane run with each per-step normals method (no cubic)
-- source: York's dissertation [T] §7.5.2, Figs 73, 74 and 75
-- look: Fig 73: the change of the mean radius (points at 0, 45 and 90
--   degrees) against time. With the connectivity normals (thick) the
--   cylinder expands and oscillates about its equilibrium; the mass matrix
--   method (long dashes) does the same, close to it; with the quadratic colour
--   function the membrane barely resists from the first steps and the gas
--   pushes it against the walls at x, y = 1.5 ([T]: "by t=0.005 ... virtually
--   no resistance", Fig 75(d)); the simple colour function (not in [T]'s Fig
--   73) does the same. Fig 74: points and normals at t = 0.01, quadratic (the
--   normals scattered); Fig 75: positions at t = 0.05 for each method
-- checks: [T]'s "similar" as a number: the mass matrix run's mean radius
--   change over two periods (t = 0.01-0.05) within 5 % of the connectivity
--   run's (our tolerance, [F] Table IV's 5 % agreement); both against the
--   equilibrium of Laplace's law with the gas compressed adiabatically,
--   p0 (R/r)^(2 gamma) = E t ln(r/R) / ((1 - nu^2) r) (ours, closed form),
--   within the same 5 %: they fall 13 % short (the ✗ shows it: the grid's
--   gas reaches a little past the membrane's line, a softer gas); the
--   quadratic run's membrane against the walls at t = 0.05 (its points
--   within a cell of x or y = 1.5: [T] Fig 75(d))
-- assumed: [T] gives no parameters for this run. The cylinder of radius 1.0
--   in quarter symmetry, walls at x, y = 1.5 (zero velocity, as [T]); the
--   normals paper's circle (assets/lua/circle_membrane.lua) scaled to it:
--   gas rho 1, p0 1000, gamma 1.4, mu 0.2, 16 ppc (clipped fill), membrane
--   rho 0.5, E 1e6, nu 0.3, t 0.1 plane stress, 181 points, point forces, cell
--   0.1, linear basis, dt 2e-5, to t = 0.05. The cubic method ([T]'s thin
--   line, Figs 74(a), 75(c)) is not run: its equations are lost in the text
-- thumb: fig73_radius.png
local out = lamina.param("out", "out/normals_cylinder_expansion")
local t_end = lamina.param("t_end", 0.05)

local R, p0, gam, E, nu, th, h = 1.0, 1000, 1.4, 1e6, 0.3, 0.1, 0.1
-- the equilibrium: bisection on p0 (R/r)^(2 gamma) - E t ln(r/R) / ((1 - nu^2) r)
local function eq_radius()
  local function F(r) return p0 * (R / r) ^ (2 * gam) - E * th * math.log(r / R) / ((1 - nu * nu) * r) end
  local a, b = R, 2 * R
  for _ = 1, 100 do
    local m = 0.5 * (a + b)
    if F(m) > 0 then a = m else b = m end
  end
  return 0.5 * (a + b)
end
local d_eq = eq_radius() - R

local methods = {
  { key = "connectivity", label = "connectivity", width = 3 },
  { key = "mass_matrix", label = "mass matrix (linear)", dashed = true },
  { key = "quadratic_colour", label = "quadratic colour" },
  { key = "colour", label = "simple colour (not in Fig 73)", width = 1 },
}
local curves, runs, hashes = {}, {}, {}
for _, m in ipairs(methods) do
  local sim = lamina.sim{ basis = "linear", domain = {0, 0, 1.5, 1.5}, cell = h, dt = 2e-5,
    boundary = { left = "symmetry", bottom = "symmetry", right = "fixed", top = "fixed" } }
  local gas = sim:body{ material = lamina.gas{ rho = 1, p = p0, gamma = gam, mu = 0.2 }, ppc = 16,
                        name = "gas", fill = "clipped",
                        region = lamina.disk{ center = {0, 0}, radius = R } }
  local mem = sim:membrane{ material = lamina.membrane{ rho = 0.5, E = E, nu = nu, thickness = th,
                                                       law = "plane_stress" },
                            curve = lamina.arc{ center = {0, 0}, radius = R, from = 0, to = 90 },
                            count = 181, force = "point", normals = m.key, orient = {0, 0},
                            name = "membrane" }
  local _ = gas
  -- [T]: "the change in the radius of material points at 0, 45, and 90 degrees are averaged"
  local rec = sim:record{ every = 2.5e-4, values = { dr = function()
    local P, s = mem:particles(), 0
    for _, i in ipairs{1, 91, 181} do s = s + math.sqrt(P.x[i] ^ 2 + P.y[i] ^ 2) - R end
    return s / 3 end } }
  local function frame(tf, fig)
    sim:at(tf, function(s)
      s:frame{ file = string.format("%s/%s_%s_t%.3f.png", out, fig, m.key, tf), width = 420, height = 440,
               window = {0, 0, 1.5, 1.5}, discs = "spacing",
               title = string.format("Fig %s: %s, t = %.2f", fig, m.label:gsub(" %(.*", ""), tf) }
    end)
  end
  if m.key == "quadratic_colour" or m.key == "colour" then frame(math.min(0.01, t_end), "74") end
  frame(t_end, "75")
  sim:run{ t_end = t_end }
  local P = mem:particles()
  local reach = 0
  for i = 1, P.n do reach = math.max(reach, P.x[i], P.y[i]) end
  runs[m.key] = { t = rec:column("t"), dr = rec:column("dr"), rec = rec, reach = reach }
  hashes[#hashes + 1] = sim:hash()
  curves[#curves + 1] = { x = runs[m.key].t, y = runs[m.key].dr, label = m.label, dashed = m.dashed,
                          width = m.width }
end
curves[#curves + 1] = { x = {0, t_end}, y = {d_eq, d_eq}, dashed = true, color = 8,
                        label = "equilibrium (Laplace, adiabatic gas; ours)" }
lamina.plot{ file = out .. "/fig73_radius.png", csv = true, width = 760, height = 440,
             title = "Fig 73: change of the mean radius (points at 0, 45, 90 deg)", xlabel = "t",
             ylabel = "delta r", legend = "best", yrange = {-0.02, 0.62}, series = curves }

local t0 = math.min(0.01, 0.2 * t_end)
local conn = runs.connectivity.rec:mean("dr", t0, t_end)
local mm = runs.mass_matrix.rec:mean("dr", t0, t_end)
local apart = 0
for i = 1, #runs.connectivity.dr do
  apart = math.max(apart, math.abs(runs.connectivity.dr[i] - runs.mass_matrix.dr[i]))
end
print(string.format("equilibrium delta r %.5f; mean over t = %g-%g: connectivity %.5f, mass matrix %.5f; "
  .. "largest distance between them %.5f; reach at the end: quadratic %.3f, colour %.3f",
  d_eq, t0, t_end, conn, mm, apart, runs.quadratic_colour.reach, runs.colour.reach))
local h64 = 0xcbf29ce484222325
for _, c in ipairs(hashes) do for i = 1, #c do h64 = (h64 ~ c:byte(i)) * 0x100000001b3 end end
lamina.report{
  mass_matrix_vs_connectivity_mean = { 100 * (mm - conn) / conn, ref = 0, tol = 5,
                                        unit = "% (mean delta r, t = 0.01-0.05; [T]: similar)" },
  connectivity_mean_dr = { conn, ref = d_eq, tol = 0.05 * d_eq,
                           unit = "(equilibrium, ours; t = 0.01-0.05; tol [F] Table IV's 5 %)" },
  mass_matrix_mean_dr = { mm, ref = d_eq, tol = 0.05 * d_eq,
                          unit = "(equilibrium, ours; t = 0.01-0.05; tol [F] Table IV's 5 %)" },
  mass_matrix_vs_connectivity_max = { apart, unit = "largest |delta r| difference ([T]: similar)" },
  quadratic_reach = { runs.quadratic_colour.reach, ref = 1.5, tol = h,
                      unit = "largest x or y of its points at the end (walls at 1.5; [T] Fig 75(d))" },
  quadratic_dr_0_005 = { runs.quadratic_colour.rec:mean("dr", 0.0045, 0.0055) / d_eq,
                         unit = "x the equilibrium at t = 0.005 ([T]: virtually no resistance)" },
  colour_reach = { runs.colour.reach, unit = "(walls at 1.5)" },
  state_hash = string.format("%016x", h64),
}
