-- V4 Sod shock tube ([F] §4.1, Fig 6; physics.md V4): 200 x 1 cells of
-- 0.005, 3 points per cell in a row (ppc = {3, 1}); left rho = 1, p = 1;
-- right rho = 0.125, p = 0.1; gamma = 1.4; the paper's artificial viscosity
-- (g = sqrt(2) dx, lambda = 0.75, c1 = c2 = 1); t = 0.143.
-- Reference: the exact Riemann solution (assets/lua/riemann.lua).
-- Checks: the shock (where the density crosses midway between the
-- post-shock plateau and the right state) within 2 cells of the exact
-- position; the post-shock plateau's pressure and density (particle means
-- between the contact and the shock) within 5 % of exact.
local riemann = require("riemann")
local dx = 0.005
local sim = lamina.sim{ domain = {0, 0, 1, dx}, cell = dx, dt = 1e-4,
                        boundary = { left = "fixed", right = "fixed",
                                     bottom = "symmetry", top = "symmetry" } }
local hi = lamina.gas{ rho = 1, p = 1, gamma = 1.4, av = true }
local lo = lamina.gas{ rho = 0.125, p = 0.1, gamma = 1.4, av = true }
local L = sim:body{ material = hi, region = lamina.rect{ x0 = 0, y0 = 0, x1 = 0.5, y1 = dx }, ppc = {3, 1} }
local R = sim:body{ material = lo, region = lamina.rect{ x0 = 0.5, y0 = 0, x1 = 1, y1 = dx }, ppc = {3, 1} }
sim:run{ t_end = 0.143 }

local exact = riemann.solve{ left = {1, 0, 1}, right = {0.125, 0, 0.1}, gamma = 1.4 }
local x_shock = 0.5 + exact.shock_speed * sim.t
local x_contact = 0.5 + exact.u_star * sim.t
local xs, rs, ps = {}, {}, {}
for _, b in ipairs{L, R} do
  local p = b:particles()
  for i = 1, p.n do xs[#xs + 1], rs[#rs + 1], ps[#ps + 1] = p.x[i], p.rho[i], p.p[i] end
end
-- shock: the last particle (from the left) above the mid density
local mid = 0.5 * (exact.rho_star_right + 0.125)
local found
for i = #xs, 2, -1 do
  if rs[i - 1] >= mid and rs[i] < mid then
    found = xs[i - 1] + (xs[i] - xs[i - 1]) * (rs[i - 1] - mid) / (rs[i - 1] - rs[i])
    break
  end
end
-- the plateau, away from the smeared contact and shock
local a, b = x_contact + 0.2 * (x_shock - x_contact), x_shock - 0.2 * (x_shock - x_contact)
local sr, sp, n = 0, 0, 0
for i = 1, #xs do
  if xs[i] > a and xs[i] < b then sr, sp, n = sr + rs[i], sp + ps[i], n + 1 end
end
local rho_pl, p_pl = sr / n, sp / n
print(string.format("V4 Sod: shock at %.4f (exact %.4f, %.2f cells off); plateau rho %.4f "
  .. "(exact %.4f, %+.2f %%), p %.4f (exact %.4f, %+.2f %%) over %d particles", found or -1,
  x_shock, math.abs((found or 0) - x_shock) / dx, rho_pl, exact.rho_star_right,
  100 * (rho_pl - exact.rho_star_right) / exact.rho_star_right, p_pl, exact.p_star,
  100 * (p_pl - exact.p_star) / exact.p_star, n))
assert(found and math.abs(found - x_shock) <= 2 * dx, "shock not within 2 cells")
assert(n >= 5 and math.abs(rho_pl - exact.rho_star_right) / exact.rho_star_right <= 0.05,
       "plateau density off by more than 5 %")
assert(math.abs(p_pl - exact.p_star) / exact.p_star <= 0.05, "plateau pressure off by more than 5 %")
