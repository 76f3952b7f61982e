-- Issue 15 item 2: a spherical gas-filled membrane, axisymmetric
-- (lamina.sim{axisymmetric = true}; src/mpm/axisym.c). The sphere of
-- radius 0.5 is a half circle in (r, z) from pole to pole, both ends on
-- the axis (its poles take eps_thth = eps_t there). Membrane E 1e6,
-- nu 0.3, t 0.1, rho 0.5, plane stress (biaxial in a ring: sigma_t =
-- E'(eps_t + nu eps_th), sigma_th = E'(eps_th + nu eps_t)); gas p 1000,
-- rho 1, gamma 1.4, mu 0.2 (the circle of [N] §8 / V6 made a sphere).
-- It starts at half the equilibrium strain, so the gas pushes it out and
-- it settles, ringing, about the sphere's equilibrium
--   sigma t = p r / 2   (both meridional and hoop),
-- half the cylinder's p r. Checked, time-averaged over the second half of
-- 0.05 s: sigma_t t and sigma_th t against p r / 2 with p the gas's
-- pressure over the enclosed space (sum V_p p_p over the half disc's volume
-- per radian, int r dA; gas:pressure(mem)) and r the points' mean distance
-- from the centre, within 3 %. The start checks that volume.
-- Measured: bspline2 with segments -1.10 % / -1.15 % (meridional / hoop),
-- with point quadrature -1.34 % / -1.13 %; linear with segments +1.85 % /
-- +0.29 %: these three are asserted. Printed only, as they miss: linear
-- with point quadrature -7.2 % / -4.8 % (cell-crossing noise), gimp with
-- segments -5.6 % / -6.7 % with 6 gas points through the membrane.
-- every gas particle outside the membrane: membrane:escaped's count beyond a
-- quarter cell plus its skin-grazers (issue 30: the count this file used)
local function outside(beyond, _, grazing) return beyond + grazing end
local p0, R, t, E, nu = 1000, 0.5, 0.1, 1e6, 0.3
local t_end = lamina.param("t_end", 0.05)

local function run(basis, force)
local sim = lamina.sim{ domain = {0, -1, 1, 1}, cell = 0.1, dt = 0.5e-4, axisymmetric = true,
                        basis = basis,
                        boundary = { left = "symmetry", bottom = "fixed", right = "fixed",
                                     top = "fixed" } }
local air = lamina.gas{ rho = 1, p = p0, gamma = 1.4, mu = 0.2 }
local skin = lamina.membrane{ rho = 0.5, E = E, nu = nu, thickness = t, law = "plane_stress" }
local gas = sim:body{ material = air, ppc = 16, name = "gas", fill = "clipped",
                      region = lamina.disk{ center = {0, 0}, radius = R } }
local eq = p0 * R / (2 * t) * (1 - nu) / E          -- equibiaxial: sigma = E eps / (1 - nu)
local mem = sim:membrane{ material = skin, count = 61, name = "membrane", force = force,
                          orient = {0, 0}, initial_strain = eq / 2,
                          curve = lamina.arc{ center = {0, 0}, radius = R, from = -90, to = 90 } }
-- the gas fills the half disc: its pressure over the enclosed volume per
-- radian is p0 at the start (clipped seeding: sum V_p = int r dA)
local pstart = gas:pressure(mem)
assert(math.abs(pstart / p0 - 1) < 2e-3, string.format("start: %.2f over the volume", pstart))
local sum_t, sum_h, sum_ref, n = 0, 0, 0, 0
local series = {}
sim:every(5e-4, function()
  local s = mem:particles()
  local st, sh, r = 0, 0, 0
  for k = 1, #s.x do
    st = st + s.sxx[k] + s.syy[k]    -- sigma_t t(x)t: its trace is sigma_t
    sh = sh + s.szz[k]
    r = r + math.sqrt(s.x[k] ^ 2 + s.y[k] ^ 2)
  end
  st, sh, r = st / #s.x, sh / #s.x, r / #s.x
  local ref = gas:pressure(mem) * r / 2   -- over the enclosed volume per radian
  series[#series + 1] = string.format("%.4f %.4f %.4f %.5f", sim.t, st * t / ref, sh * t / ref, r)
  if sim.t >= t_end / 2 then
    sum_t, sum_h, sum_ref, n = sum_t + st * t, sum_h + sh * t, sum_ref + ref, n + 1
  end
end)
sim:run{ t_end = t_end }
local et, eh = sum_t / sum_ref - 1, sum_h / sum_ref - 1
print(string.format("%s, %s: time-averaged sigma_t t / (p r / 2) - 1 = %.2f %%, sigma_th t: %.2f %%; " ..
                    "gas out %d", basis, force, 100 * et, 100 * eh, outside(mem:escaped(gas))))
print("t, sigma_t t / (p r/2), sigma_th t / (p r/2), mean r:")
for k = 1, #series, 10 do print("  " .. series[k]) end
sim:frame{ file = "axisym_sphere_" .. basis .. "_" .. force .. ".png", colour = "pressure",
           mirror = "x", title = "gas-filled sphere (axisymmetric), t = 0.05 s" }
return et, eh, outside(mem:escaped(gas))
end

for _, c in ipairs{ {"bspline2", "segment"}, {"bspline2", "point"}, {"linear", "segment"} } do
  local et, eh, out = run(c[1], c[2])
  assert(math.abs(et) < 0.03, string.format("%s %s meridional: %.2f %% (limit 3 %%)", c[1], c[2], 100 * et))
  assert(math.abs(eh) < 0.03, string.format("%s %s hoop: %.2f %% (limit 3 %%)", c[1], c[2], 100 * eh))
  assert(out == 0, "gas escaped")
end
-- measured, not asserted (they miss; see the head)
run("linear", "point")
run("gimp", "segment")
