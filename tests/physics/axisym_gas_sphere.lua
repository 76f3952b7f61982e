-- Issue 15 item 2: a gas sphere released into vacuum, axisymmetric
-- (lamina.sim{axisymmetric = true}: x is r, y is z, per radian; axisym.c).
-- Radius 0.2 m about the origin, air at rest p = 1e5 Pa, rho = 1.2, moving
-- along the axis at 5 m/s, no viscosity or artificial viscosity; the half
-- plane r >= 0 with the axis a symmetry wall, the other sides far away.
-- Exact: the mass and the axial momentum never change (momentum to
-- round-off: sum_i f_zi = 0 because sum_i dN_i/dz = 0; the hoop force is
-- radial), and the energy, kinetic + internal, is conserved; the issue asks
-- 1 %. Also checked: the released gas flows out (the outer radius grows).
local p0, rho0, R, vz = 1e5, 1.2, 0.2, 5
local basis = lamina.param("basis", "linear")
local sim = lamina.sim{ domain = {0, -0.6, 0.6, 0.6}, cell = 0.02, dt = 2e-6,
                        axisymmetric = true, basis = basis,
                        boundary = { left = "symmetry", right = "free", bottom = "free",
                                     top = "free" } }
assert(sim.axisymmetric == true)
local air = lamina.gas{ rho = rho0, p = p0, gamma = 1.4 }
local gas = sim:body{ material = air, ppc = 16, name = "gas", fill = "clipped",
                      velocity = {0, vz}, region = lamina.disk{ center = {0, 0}, radius = R } }
-- per radian: the mass is rho times the half-disc's first moment, R^3 / 1.5
-- (2 pi of it is the ball's rho 4/3 pi R^3) to the seeding's accuracy
local m0 = gas:mass()
local exact = rho0 * R ^ 3 / 1.5
assert(math.abs(m0 / exact - 1) < 2e-3, string.format("mass per radian %.6g vs %.6g", m0, exact))
local _, pz0 = sim:momentum()
local e0 = sim:energy()
local function rmax()
  local a, r = gas:particles(), 0
  for k = 1, #a.x do r = math.max(r, math.sqrt(a.x[k] ^ 2 + a.y[k] ^ 2)) end
  return r
end
-- the fronts along the axis and across it: a wrong hoop term would make
-- the cloud a spheroid
local function fronts()
  local a, fr, fz = gas:particles(), 0, 0
  for k = 1, #a.x do
    if math.abs(a.y[k]) < 0.03 then fr = math.max(fr, a.x[k]) end
    if a.x[k] < 0.03 then fz = math.max(fz, a.y[k]) end
  end
  return fr, fz
end
local r0 = rmax()
local de, dp = 0, 0
sim:every(1e-5, function()
  local e = sim:energy()
  local _, pz = sim:momentum()
  de = math.max(de, math.abs(e.total / e0.total - 1))
  dp = math.max(dp, math.abs(pz / pz0 - 1))
end)
sim:run{ t_end = 1.2e-4 }
local e1 = sim:energy()
local frac = e1.kinetic / e1.total
print(string.format("%s: mass %.17g -> %.17g; axial momentum change max %.3g; energy change max %.4f %%; " ..
                    "kinetic share %.3f (from %.4f); outer radius %.3f -> %.3f",
                    basis, m0, gas:mass(), dp, 100 * de, frac, e0.kinetic / e0.total, r0, rmax()))
local fr, fz = fronts()
local zc = select(2, gas:com())
print(string.format("front across the axis %.4f, along it %.4f (from the centre %.4f)", fr, fz - zc, zc))
sim:frame{ file = "axisym_gas_sphere_" .. basis .. ".png", colour = "pressure", mirror = "x",
           title = "gas sphere released into vacuum (axisymmetric), t = 0.12 ms" }
assert(gas:mass() == m0, "mass changed")
assert(dp < 1e-12, string.format("axial momentum changed by %.3g", dp))
assert(de < 0.01, string.format("energy changed by %.3f %% (limit 1 %%)", 100 * de))
assert(frac > 2 * e0.kinetic / e0.total, "the gas did not expand")
assert(math.abs(fr - (fz - zc)) < 0.02, "the cloud is not spherical")
assert(rmax() > r0 + 0.02, "the outer radius did not grow")
