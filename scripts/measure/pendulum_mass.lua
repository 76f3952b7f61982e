-- pendulum_mass.lua - membrane_pendulum_no_wrinkle's scene ([T] §5.7.3,
-- Table 1: linear basis, segment forces, cell 0.1, pure FLIP, the 3.3 end
-- mass; scripts/paper/membrane_pendulum_no_wrinkle.lua) on the lumped mass
-- and on lamina.sim{mass = "membrane"}, at several point counts: the rms of
-- theta(t) against our bar FEM (assets/lua/barfem.lua) over t <= 1.8,
-- without and with the wrinkle law (issue 30 item 2; docs/robustness.md
-- "Why the segment dog-bone leaks", the table after it).
-- basis and dtf (dt c / h) set the basis and the step: the cause of the
-- difference ("Why the pendulum is worse on the consistent mass") is the
-- linear basis' cell crossing, measured with --set basis=bspline2 --set dtf=0.5.
--   lamina run scripts/measure/pendulum_mass.lua [--set counts="36 38 40 42 44"]
--              [--set basis=linear] [--set dtf=0.63]
local counts = lamina.param("counts", "36 38 40 42 44")
local basis = lamina.param("basis", "linear")
local dtf = tonumber(lamina.param("dtf", "0.63"))
local barfem = require("barfem")
local E, L, m, g, th0, rho, t = 1e6, 0.73, 3.3, 20, 19.8, 0.1, 0.1
local c = math.sqrt(E / rho)
local px, py = 0.6, 1.0
local mx, my = px + L * math.sin(math.rad(th0)), py - L * math.cos(math.rad(th0))
local h, t_end = 0.1, 1.8
local fem = barfem.run{ from = {px, py}, to = {mx, my}, elements = 20, rho = rho, A = t, E = E,
                        end_mass = m, g = {0, -g}, one_way = false, t_end = t_end, every = 1e-3, safety = 0.9 }
local function run(one_way, n, mass)
  local sim = lamina.sim{ basis = basis, domain = {0, 0, 1.2, 1.0}, cell = h, dt = dtf * h / c,
                          gravity = {0, -g}, mass = mass }
  local wire = lamina.membrane{ rho = rho, E = E, nu = 0, thickness = t, law = "uniaxial", one_way = one_way }
  local s = sim:membrane{ force = "segment", material = wire, count = n, end_mass = m, name = "string",
                          curve = lamina.segment{ from = {px, py}, to = {mx, my} } }
  local rec = sim:record{ every = 2e-3, angle = { theta = s } }
  sim:run{ t_end = t_end }
  local tt, th = rec:column("t"), rec:column("theta")
  local se = 0
  for i = 1, #tt do se = se + (th[i] - barfem.at(fem.t, fem.theta, tt[i]))^2 end
  return math.sqrt(se / #tt)
end
print("points  law      lumped   membrane  (rms theta vs our FEM, deg)")
for w in counts:gmatch("%d+") do
  local n = tonumber(w)
  for _, ow in ipairs{false, true} do
    print(string.format("%6d  %-7s  %.4f   %.4f", n, ow and "one-way" or "two-way", run(ow, n, "lumped"), run(ow, n, "membrane")))
  end
end
