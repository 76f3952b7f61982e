-- title: The one-way (wrinkle) law: Young's modulus zero in compression, as the engine applies it
-- source: York, Sulsky & Schreyer 1999 (membranes), §3.2, Fig 13; York's dissertation §5.2, Fig 21
-- look: (a) the effective Young's modulus E_t against the tangent strain: 0 for
--   negative strain, E for positive (the papers' step); (b) the tangential stress
--   it gives: zero in compression, E eps in tension, beside the two-way law's
--   straight line. The markers are the engine's values, the lines the closed form.
-- checks: the engine's tangential stress sigma_t = t.sigma.t of a string at 30 degrees,
--   held at a prescribed strain, against the closed form (one-way: E max(eps, 0);
--   two-way: E eps) over eps in [-0.02, 0.02]; the slope between neighbouring
--   markers against E_t (0 or E)
-- assumed: E = 1e6 (the spring-mass's, [M] §3.1.1); the papers' graphs carry no
--   numbers, so the strain range is ours
-- thumb: law_wrinkle.png
local out = lamina.param("out", "out/law_wrinkle")

local E, angle = 1e6, math.rad(30)
local c, s = math.cos(angle), math.sin(angle)

-- A string of five points at 30 degrees, every point held, given a uniform
-- initial strain; after one tiny step the engine has rebuilt each point's stress
-- from its strain (docs/api.md, lamina.membrane), and sigma_t = t . sigma . t.
local function engine_stress(eps, one_way)
  local sim = lamina.sim{ basis = "linear", domain = {0, 0, 1, 1}, cell = 0.1, dt = 1e-7 }
  local mat = lamina.membrane{ rho = 1, E = E, nu = 0, thickness = 0.01, one_way = one_way }
  local str = sim:membrane{ material = mat, count = 5, initial_strain = eps,
                            curve = lamina.segment{ from = {0.3, 0.3},
                                                    to = {0.3 + 0.4 * c, 0.3 + 0.4 * s} } }
  str:pin{ points = "all" }
  sim:run{ t_end = 1e-7 }
  local p = str:particles()
  local k = 3
  return p.sxx[k] * c * c + 2 * p.sxy[k] * c * s + p.syy[k] * s * s, p.et[k]
end

local strains, sig1, sig2, et1 = {}, {}, {}, {}
local worst1, worst2, worst_e = 0, 0, 0
for i = -10, 10 do
  local eps = 0.002 * i
  strains[#strains + 1] = eps
  local a, et = engine_stress(eps, true)
  local b = engine_stress(eps, false)
  sig1[#sig1 + 1], sig2[#sig2 + 1], et1[#et1 + 1] = a, b, et
  worst1 = math.max(worst1, math.abs(a - E * math.max(eps, 0)))
  worst2 = math.max(worst2, math.abs(b - E * eps))
  worst_e = math.max(worst_e, math.abs(et - eps))
end
-- E_t between neighbouring markers (the slope of the engine's curve)
local mid, slope, worst_slope = {}, {}, 0
for i = 2, #strains do
  local m = 0.5 * (strains[i - 1] + strains[i])
  local k = (sig1[i] - sig1[i - 1]) / (strains[i] - strains[i - 1])
  mid[#mid + 1], slope[#slope + 1] = m, k
  worst_slope = math.max(worst_slope, math.abs(k - (m > 0 and E or 0)))
end

local fig = lamina.figure{ width = 1000, height = 480, panels = {2, 1},
  title = "[M] Fig 13 / [T] Fig 21: one-way stiffness to simulate wrinkles" }
-- (a) E_t against eps: the papers' graph
local sx, sy = 1 / 0.025, 1 / 1.25e6   -- strain and modulus to panel units
fig:panel{ index = 1, window = {-1.05, -0.25, 1.05, 1.15},
           title = "(a) effective Young's modulus E_t",
           caption = string.format("markers: the engine's slope; largest miss %.3g of E", worst_slope / E) }
fig:polyline{ points = {{-1, 0}, {1, 0}}, colour = "black", width = 1 }
fig:polyline{ points = {{0, -0.1}, {0, 1.05}}, colour = "black", width = 1 }
fig:polyline{ points = {{-0.02 * sx, 0}, {0, 0}, {0, E * sy}, {0.02 * sx, E * sy}},
              colour = "exact", width = 2.5 }
local pts = {}
for i = 1, #mid do pts[i] = {mid[i] * sx, slope[i] * sy} end
fig:points{ points = pts, style = "circle", size = 7, colour = "computed" }
fig:text{ text = "tangent strain eps_t", at = {1.0, -0.2}, align = "right" }
fig:polyline{ points = {{-0.8, -0.02}, {-0.8, 0.02}}, colour = "black" }
fig:polyline{ points = {{0.8, -0.02}, {0.8, 0.02}}, colour = "black" }
fig:text{ text = "E_t", at = {0.03, 1.07} }
fig:text{ text = "E = 1e6", at = {-0.05, E * sy}, align = "right" }
fig:text{ text = "0 (compression: wrinkle)", at = {-0.5, 0.05}, align = "center" }
fig:text{ text = "-0.02", at = {-0.8, -0.1}, align = "center" }
fig:text{ text = "0.02", at = {0.8, -0.1}, align = "center" }
-- (b) sigma_t against eps
local ty = 1 / 25000
fig:panel{ index = 2, window = {-1.05, -1.05, 1.05, 1.05},
           title = "(b) tangential stress sigma_t",
           caption = string.format("engine against closed form: one-way %.2g, two-way %.2g", worst1, worst2) }
fig:polyline{ points = {{-1, 0}, {1, 0}}, colour = "black", width = 1 }
fig:polyline{ points = {{0, -0.95}, {0, 0.95}}, colour = "black", width = 1 }
fig:polyline{ points = {{-0.02 * sx, -0.02 * E * ty}, {0.02 * sx, 0.02 * E * ty}},
              colour = "grey", width = 1.5, dashed = true }
fig:polyline{ points = {{-0.02 * sx, 0}, {0, 0}, {0.02 * sx, 0.02 * E * ty}},
              colour = "exact", width = 2.5 }
local p1, p2 = {}, {}
for i = 1, #strains do
  p1[i] = {strains[i] * sx, sig1[i] * ty}
  p2[i] = {strains[i] * sx, sig2[i] * ty}
end
fig:points{ points = p2, style = "dot", size = 5, colour = "grey" }
fig:points{ points = p1, style = "circle", size = 7, colour = "computed" }
fig:text{ text = "eps_t", at = {1.0, -0.2}, align = "right" }
fig:text{ text = "-0.02", at = {-0.8, -0.1}, align = "center" }
fig:text{ text = "0.02", at = {0.8, -0.1}, align = "center" }
fig:polyline{ points = {{-0.8, -0.02}, {-0.8, 0.02}}, colour = "black" }
fig:polyline{ points = {{0.8, -0.02}, {0.8, 0.02}}, colour = "black" }
fig:polyline{ points = {{-0.02, 0.8}, {0.02, 0.8}}, colour = "black" }
fig:text{ text = "sigma_t", at = {0.03, 0.9} }
fig:text{ text = "2e4", at = {-0.05, 0.8}, align = "right" }
fig:text{ text = "one-way: engine (circles),", at = {-0.95, 0.45}, colour = "computed" }
fig:text{ text = "closed form (line)", at = {-0.95, 0.33}, colour = "computed" }
fig:text{ text = "two-way: engine (dots),", at = {0.1, -0.5}, colour = "grey" }
fig:text{ text = "E eps (dashed)", at = {0.1, -0.62}, colour = "grey" }
fig:write(out .. "/law_wrinkle.png")

print(string.format("one-way: largest |sigma - E max(eps,0)| = %.3g; two-way: largest |sigma - E eps| = %.3g; "
  .. "slope miss %.3g; strain readback %.3g", worst1, worst2, worst_slope, worst_e))
lamina.report{
  one_way_stress_error = { worst1 / (0.02 * E), ref = 0, tol = 1e-9,
                           unit = "of E eps_max (closed form E max(eps, 0), ours)" },
  two_way_stress_error = { worst2 / (0.02 * E), ref = 0, tol = 1e-9,
                           unit = "of E eps_max (closed form E eps, ours)" },
  modulus_step_error = { worst_slope / E, ref = 0, tol = 1e-6,
                         unit = "of E (E_t: 0 below eps = 0, E above; [M] Fig 13)" },
}
