-- Issue 13 item 6: Sod on the 2000 paper's tube (200 x 1 cells of 0.005,
-- ppc {3, 1}, the paper's artificial viscosity, t = 0.143; assets/lua/sod.lua)
-- against the exact Riemann solution (assets/lua/riemann.lua), where the
-- papers' bilinear basis is weakest: the plateau LEFT of the contact (the
-- gas that came through the rarefaction) and the rarefaction itself.
-- Checks, with the quadratic B-spline (lamina.sim{basis = "bspline2"}):
--   * the mean pressure between the rarefaction's tail and the contact
--     (a fifth of the gap kept clear at each end) within 3 % of exact;
--   * no particle there more than 10 % off;
--   * in the rarefaction (a tenth kept clear at each end) no particle's
--     pressure more than 5 % of the jump p_left - p* from the exact fan.
-- Measured: bspline2 -2.15 %, 5.1 %, 2.6 %; the papers' linear basis
-- -11.2 %, 13.9 %, 27 %; GIMP -5.5 %, 7.3 %, 3.9 % (printed, not asserted:
-- docs/robustness.md). The particle pressure is (gamma - 1) rho e with the
-- continuity density; the dynamics do not use rho (V p = (gamma - 1) m e),
-- and with the linear basis both rho (-9 %) and e (-2.5 %) come out low.
local sod = require("sod")
local ex = sod.exact
local g, pl, rl = 1.4, 1, 1
local cl = math.sqrt(g * pl / rl)

local function run(basis)
  local sim, L, R = sod.setup{ dx = 0.005, basis = basis }
  sim:run{ t_end = 0.143 }
  local f, t = sod.profile{L, R}, sim.t
  local xh = 0.5 - cl * t                                            -- fan head
  local xt = 0.5 + (ex.u_star - cl * (ex.p_star / pl)^((g - 1) / (2 * g))) * t   -- tail
  local xc = 0.5 + ex.u_star * t                                     -- contact
  local a, b = xt + 0.2 * (xc - xt), xc - 0.2 * (xc - xt)
  local sp, n, worst, osc = 0, 0, 0, 0
  for i = 1, #f.x do
    if f.x[i] > a and f.x[i] < b then
      sp, n = sp + f.p[i], n + 1
      worst = math.max(worst, math.abs(f.p[i] / ex.p_star - 1))
    end
    if f.x[i] > xh + 0.1 * (xt - xh) and f.x[i] < xt - 0.1 * (xt - xh) then
      local _, _, pe = ex:sample((f.x[i] - 0.5) / t)
      osc = math.max(osc, math.abs(f.p[i] - pe) / (pl - ex.p_star))
    end
  end
  local mean = sp / n
  print(string.format("%-8s: left plateau mean p %.4f (exact %.4f, %+.2f %%) over %d particles, "
    .. "worst %.1f %%; rarefaction worst |p - exact| %.1f %% of the jump", basis, mean, ex.p_star,
    100 * (mean / ex.p_star - 1), n, 100 * worst, 100 * osc))
  return math.abs(mean / ex.p_star - 1), worst, osc, n
end

local m, w, o, n = run("bspline2")
assert(n >= 10, "too few particles on the left plateau")
assert(m <= 0.03, string.format("left plateau mean %.2f %% off (limit 3 %%)", 100 * m))
assert(w <= 0.10, string.format("a left-plateau particle %.1f %% off (limit 10 %%)", 100 * w))
assert(o <= 0.05, string.format("rarefaction oscillation %.1f %% of the jump (limit 5 %%)", 100 * o))
run("linear")   -- the papers' basis: fails all three (printed)
run("gimp")     -- fails the mean (printed)
