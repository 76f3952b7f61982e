-- V3 pendulum ([M] §3.1.2, Figs 8-12; [T] §5.7; docs/physics.md V3), reduced:
-- cells 0.2 / 0.1 / 0.05 (the gallery adds 0.025). L = 0.73, end mass 3.3,
-- g = 20, theta0 = 19.8 deg, E = 1e6, nu = 0, one-way law on.
-- The papers disagree on rho and thickness (same mass per length, EA 10x
-- apart); we use the dissertation's Table 1 / Box 7: rho = 0.1, t = 0.1,
-- with its point counts 20 / 40 / 80 and dt = 2e-5 at cell 0.1 (0.63 dt_c).
-- With pure FLIP the light string's cell-crossing noise (kicks of order
-- T ds / (rho t h^2)) pumps energy into the string points until the run
-- fails near t = 1.2 at cells <= 0.05 (measured); a 0.1 % PIC blend
-- (pic = 0.001) removes it at every refinement and is used throughout.
-- Reference: an explicit bar-element FEM solution computed here
-- (assets/lua/barfem.lua), as [M] Fig 11.
-- Checks: the rms error of theta(t) against the FEM over 1.5 periods falls
-- with every refinement; at the finest grid the swing amplitude (largest
-- |theta| after t = 0.3) is within 10 % of the FEM's.
local barfem = require("barfem")
local E, L, m, g, th0, rho, t = 1e6, 0.73, 3.3, 20, 19.8, 0.1, 0.1
local c = math.sqrt(E / rho)
local px, py = 0.6, 1.0
local mx, my = px + L * math.sin(math.rad(th0)), py - L * math.cos(math.rad(th0))
local T_end = 1.8

local fem = barfem.run{ from = {px, py}, to = {mx, my}, elements = 10, rho = rho, A = t, E = E,
                        end_mass = m, g = {0, -g}, one_way = true, t_end = T_end,
                        every = 1e-3, safety = 0.9 }

local function swing(h, n)
  local sim = lamina.sim{ basis = "linear", domain = {0, 0, 1.2, 1.0}, cell = h, dt = 0.63 * h / c,
                          gravity = {0, -g}, pic = 0.001 }
  local wire = lamina.membrane{ rho = rho, E = E, nu = 0, thickness = t, one_way = true }
  local s = sim:membrane{ force = "point", material = wire, count = n, end_mass = m,
                          curve = lamina.segment{ from = {px, py}, to = {mx, my} } }
  local rec = sim:record{ every = 1e-3, angle = { theta = s } }
  sim:run{ t_end = T_end }
  local ts, th = rec:column("t"), rec:column("theta")
  local se, amp, amp_fem = 0, 0, 0
  for i = 1, #ts do
    local f = barfem.at(fem.t, fem.theta, ts[i])
    se = se + (th[i] - f)^2
    if ts[i] > 0.3 then
      amp, amp_fem = math.max(amp, math.abs(th[i])), math.max(amp_fem, math.abs(f))
    end
  end
  return math.sqrt(se / #ts), amp, amp_fem
end

local prev
for _, r in ipairs{ {0.2, 20}, {0.1, 40}, {0.05, 80} } do
  local err, amp, amp_fem = swing(r[1], r[2])
  print(string.format("V3 cell %.3f, %d points: rms theta error %.3f deg, amplitude %.2f "
    .. "(FEM %.2f, %+.1f %%)", r[1], r[2], err, amp, amp_fem, 100 * (amp - amp_fem) / amp_fem))
  assert(not prev or err < prev, "the error must fall with refinement")
  prev = err
  if r[1] == 0.05 then
    assert(math.abs(amp - amp_fem) / amp_fem <= 0.10, "finest amplitude not within 10 % of the FEM")
  end
end
