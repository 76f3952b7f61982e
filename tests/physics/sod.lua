-- V4 Sod shock tube ([F] §4.1, Fig 6; docs/physics.md V4): 200 x 1 cells of
-- 0.005, 3 points per cell in a row (ppc = {3, 1}); left rho = 1, p = 1;
-- right rho = 0.125, p = 0.1; gamma = 1.4; the paper's artificial viscosity
-- (g = sqrt(2) dx, lambda = 0.75, c1 = c2 = 1); t = 0.143 (assets/lua/sod.lua).
-- Reference: the exact Riemann solution (assets/lua/riemann.lua).
-- Checks: the shock (where the density crosses midway between the
-- post-shock plateau and the right state) within 2 cells of the exact
-- position; the post-shock plateau's pressure and density (particle means
-- between the contact and the shock) within 5 % of exact.
local sod = require("sod")
local dx = 0.005
local sim, L, R = sod.setup{ dx = dx }
sim:run{ t_end = 0.143 }
local ex = sod.exact
local r = sod.measure(sod.profile{L, R}, sim.t)
print(string.format("V4 Sod: shock at %.4f (exact %.4f, %.2f cells off); plateau rho %.4f "
  .. "(exact %.4f, %+.2f %%), p %.4f (exact %.4f, %+.2f %%) over %d particles", r.shock or -1,
  r.x_shock, math.abs((r.shock or 0) - r.x_shock) / dx, r.rho_plateau, ex.rho_star_right,
  100 * (r.rho_plateau - ex.rho_star_right) / ex.rho_star_right, r.p_plateau, ex.p_star,
  100 * (r.p_plateau - ex.p_star) / ex.p_star, r.n))
assert(r.shock and math.abs(r.shock - r.x_shock) <= 2 * dx, "shock not within 2 cells")
assert(r.n >= 5 and math.abs(r.rho_plateau - ex.rho_star_right) / ex.rho_star_right <= 0.05,
       "plateau density off by more than 5 %")
assert(math.abs(r.p_plateau - ex.p_star) / ex.p_star <= 0.05, "plateau pressure off by more than 5 %")
