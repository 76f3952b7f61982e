-- The isentrope through Sod's rarefaction (issue 32, sod32; docs/robustness.md
-- "Sod on the papers' basis"). In the fan the exact flow is isentropic, so
-- p / rho^gamma stays at its left value 1 at every point. The gas's update
-- ([F] eqs 16, 22-23: rho <- rho / (1 + eps), e <- e - (gamma - 1) e eps with
-- eps = tr de = dt div v, p at e^k) keeps it a step to second order:
-- s^{k+1} / s^k = (1 - (gamma - 1) eps)(1 + eps)^(gamma - 1)
--               = 1 - gamma (gamma - 1) / 2 eps^2 + O(eps^3),
-- so the update loses energy in expansion, and over a point's passage the
-- loss is gamma (gamma - 1) / 2 dt INT (div v)^2 dt: first order in dt.
-- On the exact centred fan (Toro §4.4.3; xi = (x - 0.5) / t) div v = a / t,
-- a = 2 / (gamma + 1), and a point's xi moves as t dxi/dt = a c_L - k xi,
-- k = (gamma - 1) / (gamma + 1), from the head -c_L at the time t_e it
-- entered: xi - xi_eq = (-c_L - xi_eq)(t / t_e)^(-k), xi_eq = a c_L / k. So
-- the loss of a point now at xi is gamma (gamma - 1) / 2 dt a^2 (1 / t_e -
-- 1 / t), the closed form this test computes for each point (ours). The
-- grid cannot give div v = a / t while the fan is a few cells wide, so the
-- run loses less than it on a smooth basis (the quadratic B-spline: 0.73 of
-- it); on the papers' bilinear basis the points' div v also carries the
-- noise of cell crossings, whose square adds (4.2 times it). Asserted, on
-- [F]'s tube without viscosity ({3, 1} points a cell, cell 0.005, fan's
-- inner 80 % at t = 0.143), at dt = 1e-4 and 5e-5, both bases:
--  * the loss is negative (energy lost, not gained) and first order in dt:
--    the ratio of the two within 2 +- 0.1 (order 1 +- 0.07);
--  * on the quadratic B-spline it is at most the closed form's;
--  * at the pages' dt = 1e-4 it is below 0.05 % on both: the update is not
--    the left plateau's -9 % on gas_sod_shock_tube (the continuity
--    density's drift is, docs/robustness.md).
local riemann = require("riemann")
local g = 1.4
local ex = riemann.solve{ left = {1, 0, 1}, right = {0.125, 0, 0.1}, gamma = g }
local cL = math.sqrt(g)
local a, k = 2 / (g + 1), (g - 1) / (g + 1)
local xi_eq = a * cL / k

local function fan(basis, dt)
  local h = 0.005
  local sim = lamina.sim{ domain = {0, 0, 1, h}, cell = h, dt = dt, basis = basis,
                          boundary = { left = "fixed", right = "fixed", bottom = "symmetry",
                                       top = "symmetry" } }
  local L = sim:body{ material = lamina.gas{ rho = 1, p = 1, gamma = g }, ppc = {3, 1},
                      region = lamina.rect{ x0 = 0, y0 = 0, x1 = 0.5, y1 = h } }
  sim:body{ material = lamina.gas{ rho = 0.125, p = 0.1, gamma = g }, ppc = {3, 1},
            region = lamina.rect{ x0 = 0.5, y0 = 0, x1 = 1, y1 = h } }
  sim:run{ t_end = 0.143 }
  local t = sim.t
  local xi_head = -cL
  local xi_tail = ex.u_star - cL * ex.p_star ^ ((g - 1) / (2 * g))
  local q = L:particles()
  local s, pred, n = 0, 0, 0
  for i = 1, q.n do
    local xi = (q.x[i] - 0.5) / t
    if xi > xi_head + 0.1 * (xi_tail - xi_head) and xi < xi_tail - 0.1 * (xi_tail - xi_head) then
      s = s + q.p[i] / q.rho[i] ^ g - 1
      local te = t * ((xi_eq - xi) / (xi_eq + cL)) ^ (1 / k)
      pred = pred - g * (g - 1) / 2 * dt * a * a * (1 / te - 1 / t)
      n = n + 1
    end
  end
  assert(n >= 40, basis .. ": too few points in the fan: " .. n)
  return s / n, pred / n, n
end

for _, basis in ipairs{"linear", "bspline2"} do
  local s1, p1, n = fan(basis, 1e-4)
  local s2, p2 = fan(basis, 5e-5)
  print(string.format("%s: s / s_L - 1 over the fan (%d points): %.3e at dt 1e-4, %.3e at 5e-5 "
    .. "(ratio %.3f); the closed form on the exact fan %.3e / %.3e (run / closed form %.2f)",
    basis, n, s1, s2, s1 / s2, p1, p2, s1 / p1))
  assert(s1 < 0 and s2 < 0, basis .. ": the explicit update should lose energy in expansion")
  assert(math.abs(s1 / s2 - 2) <= 0.1,
         string.format("%s: not first order in dt: ratio %.3f", basis, s1 / s2))
  assert(math.abs(s1) < 5e-4, string.format("%s: the fan's entropy %.3e at dt 1e-4", basis, s1))
  if basis == "bspline2" then
    assert(s1 >= p1 and s2 >= p2,
           string.format("bspline2: loses more than the closed form: %.3e < %.3e", s1, p1))
  end
end
