-- Issue 15 item 2: Lamé's thick-walled cylinder under internal pressure,
-- axisymmetric (lamina.sim{axisymmetric = true}; src/mpm/axisym.c).
-- A steel-like annulus a = 0.2 <= r <= b = 0.4 (E 2e8, nu 0.3, rho 1000)
-- is loaded by a gas core (r < a, p 1e5, rho 1, gamma 1.4): the pressure
-- load is real gas in the same grid, no prescribed traction. The bottom and
-- top are symmetry walls, so the cylinder is long (eps_zz = 0), and the
-- outer surface is free. Exact, for the inner pressure p:
--   sigma_rr = A - B / r^2, sigma_thth = A + B / r^2, sigma_zz = 2 nu A,
--   A = p a^2 / (b^2 - a^2), B = p a^2 b^2 / (b^2 - a^2).
-- The solid starts unloaded and rings about equilibrium; a PIC blend
-- (pic = 0.1) damps the ringing, and the stresses and the gas pressure are
-- averaged over the second half of the run (0.03 s, about 7 periods of the
-- wall's breathing mode); the particles are compared in bins of one cell,
-- away from the surfaces (one cell in from each). Issue: within 2 % of p.
-- Measured (cell 0.02): bspline2 0.48 %, gimp 0.62 % (hoop stress the
-- larger error, about +0.3 % of p; sigma_rr within 0.3 %); with pic =
-- 0.05 and half the run the ringing left in the mean gives 2.4 %.
-- Not run: the bilinear basis. With FLIP, gas at rest at uniform pressure
-- is unstable in this form on the bilinear hats (a perturbation of 1e-12
-- m/s grows to 100 m/s in 4 ms, the same in physical time at half the dt,
-- so a spatial mode, not the step; pic = 1 or either 3 x 3 basis holds it
-- at round-off); the run with linear and pic = 0.2 loses 7 % of the gas
-- volume to it and misses Lamé by 9.3 % of p. docs/decisions.md.
local a, b, p0, E, nu = 0.2, 0.4, 1e5, 2e8, 0.3
local h = lamina.param("cell", 0.02)
local t_end = lamina.param("t_end", 0.06)

local function run(basis)
local sim = lamina.sim{ domain = {0, 0, 0.5, 4 * h}, cell = h, dt = 0.1 * h / 450,
                        axisymmetric = true, basis = basis, pic = lamina.param("pic", 0.1),
                        boundary = { left = "symmetry", bottom = "symmetry", top = "symmetry",
                                     right = "free" } }
local air = lamina.gas{ rho = 1, p = p0, gamma = 1.4 }
local steel = lamina.elastic{ rho = 1000, E = E, nu = nu }
local gas = sim:body{ material = air, ppc = 16, name = "gas",
                      region = lamina.rect{ x0 = 0, y0 = 0, x1 = a, y1 = 4 * h } }
local wall = sim:body{ material = steel, ppc = 16, name = "wall",
                       region = lamina.rect{ x0 = a, y0 = 0, x1 = b, y1 = 4 * h } }
local nb = math.floor((b - a) / h + 0.5)
local srr, shh, szz, cnt = {}, {}, {}, {}
for k = 1, nb do srr[k], shh[k], szz[k], cnt[k] = 0, 0, 0, 0 end
local psum, nsamp = 0, 0
sim:every(2e-5, function()
  if sim.t < t_end / 2 then return end
  local s = wall:particles()
  for k = 1, #s.x do
    local i = math.floor((s.x[k] - a) / h) + 1
    if i >= 1 and i <= nb then
      srr[i] = srr[i] + s.sxx[k]
      shh[i] = shh[i] + s.szz[k]
      szz[i] = szz[i] + s.syy[k]
      cnt[i] = cnt[i] + 1
    end
  end
  psum = psum + gas:pressure("particles")
  nsamp = nsamp + 1
end)
sim:run{ t_end = t_end }
local p = psum / nsamp
local A, B = p * a * a / (b * b - a * a), p * a * a * b * b / (b * b - a * a)
print(string.format("%s, cell %g: mean gas pressure %.1f (start %.0f)", basis, h, p, p0))
print("   r      srr/p  exact   shh/p  exact   szz/p  exact")
local worst = 0
for i = 1, nb do
  local r = a + (i - 0.5) * h
  local mrr, mhh, mzz = srr[i] / cnt[i], shh[i] / cnt[i], szz[i] / cnt[i]
  local err = math.max(math.abs(mrr - (A - B / r ^ 2)), math.abs(mhh - (A + B / r ^ 2)),
                       math.abs(mzz - 2 * nu * A)) / p
  local inside = i > 1 and i < nb
  if inside then worst = math.max(worst, err) end
  print(string.format("%6.3f  %6.3f %6.3f  %6.3f %6.3f  %6.3f %6.3f  %s%.2f %%", r, mrr / p,
                      (A - B / r ^ 2) / p, mhh / p, (A + B / r ^ 2) / p, mzz / p, 2 * nu * A / p,
                      inside and "" or "(surface) ", 100 * err))
end
print(string.format("worst error away from the surfaces: %.2f %% of p (limit 2 %%)", 100 * worst))
sim:frame{ file = "axisym_lame_" .. basis .. ".png", colour = "sxx", mirror = "x", width = 900, height = 300,
           title = "Lamé cylinder, axisymmetric: sigma_rr (gas core, elastic wall)" }
return worst
end

for _, basis in ipairs{"bspline2", "gimp"} do
  local worst = run(basis)
  assert(worst < 0.02, string.format("Lamé, %s: %.2f %% of p (limit 2 %%)", basis, 100 * worst))
end
