-- V1 spring-mass ([M] §3.1.1, Figs 5-6; docs/physics.md V1): a string of 10
-- points from y = 1.99 to 1.69 (L = 0.3), A = 0.1, E = 1e6, rho = 0.1,
-- nu = 0, the last point a heavy mass 3.33 (10 000x the others), g = -250,
-- cell 0.1, dt_c = h / sqrt(E/rho) = 3.16e-5.
-- Analytic: k = AE/L, period 2 pi sqrt(mL/(AE)) = 0.01987, static
-- deflection m g L/(AE) = 0.0025 (the mass starts at rest at the
-- unstretched length, so it swings between 0 and 0.005 about it).
-- Checks: period within 2 %, mean deflection within 5 % (at dt_c);
-- total energy at 1.6 dt_c: its drift (the change of its mean over a period,
-- first period to fifth) within 1 % of the largest kinetic energy, and its
-- oscillation within a period no larger than at dt_c (measured: 2.4 % and
-- 2.5 % of the largest kinetic energy: the point-wise strain energy of the
-- 10 points is not exactly the spring's 1/2 k d^2); at 1.7 dt_c the run is
-- unstable (it blows up, [M] Fig 6b).
local E, A, rho, L, m, g = 1e6, 0.1, 0.1, 0.3, 3.33, -250
local h = 0.1
local dtc = h / math.sqrt(E / rho)
local T = 2 * math.pi * math.sqrt(m * L / (A * E))
local d_static = m * -g * L / (A * E)

local function run(factor, t_end)
  -- the string on the node line x = 0.1: the side walls' nodes get no mass
  local sim = lamina.sim{ basis = "linear", domain = {0, 0, 0.2, 2.0}, cell = h, dt = factor * dtc,
                          gravity = {0, g}, courant = 1.7,
                          boundary = { left = "symmetry", right = "symmetry" } }
  local wire = lamina.membrane{ rho = rho, E = E, nu = 0, thickness = A, law = "uniaxial" }
  local s = sim:membrane{ force = "point", material = wire, count = 10, end_mass = m,
                          curve = lamina.segment{ from = {0.1, 1.99}, to = {0.1, 1.69} } }
  local rec = sim:record{ every = sim.dt, energy = true, points = { mass = {s, -1} } }
  local ok, err = pcall(sim.run, sim, { t_end = t_end })
  return rec, ok, err
end

-- period and mean deflection at dt_c, over 5 periods
local rec = run(1.0, 5 * T)
local t, y = rec:column("t"), rec:column("mass_y")
local up = {}
for i = 2, #t do
  local a, b = 1.69 - y[i - 1] - d_static, 1.69 - y[i] - d_static
  if a < 0 and b >= 0 then up[#up + 1] = t[i - 1] + (t[i] - t[i - 1]) * (-a) / (b - a) end
end
assert(#up >= 4, "expected 4 or more upward crossings, got " .. #up)
local period = (up[#up] - up[1]) / (#up - 1)
local mean = 1.69 - rec:mean("mass_y", up[1], up[#up])
print(string.format("V1 dt_c: period %.6f (analytic %.6f, %+.2f %%), mean deflection %.6f "
  .. "(analytic %.6f, %+.2f %%)", period, T, 100 * (period - T) / T, mean, d_static,
  100 * (mean - d_static) / d_static))
assert(math.abs(period - T) / T < 0.02, "period off by more than 2 %")
assert(math.abs(mean - d_static) / d_static < 0.05, "static deflection off by more than 5 %")

-- energy at dt_c and 1.6 dt_c: drift of the period mean, and oscillation
local function energy(factor)
  local r, ok = run(factor, 5 * T)
  assert(ok, "the run at " .. factor .. " dt_c must be stable")
  local kin = r:column("kinetic")
  local kmax = 0
  for i = 1, #kin do kmax = math.max(kmax, kin[i]) end
  local tot = r:column("total")
  local swing = 0
  for i = 1, #tot do swing = math.max(swing, math.abs(tot[i] - tot[1])) end
  local drift = math.abs(r:mean("total", 4 * T, 5 * T) - r:mean("total", 0, T))
  return drift, swing, kmax
end
local _, swing10 = energy(1.0)
local drift, swing16, kmax = energy(1.6)
print(string.format("V1 1.6 dt_c: energy drift %.4g = %.3f %% of the largest kinetic energy "
  .. "%.4g; oscillation %.3f %% (%.3f %% at dt_c)", drift, 100 * drift / kmax, kmax,
  100 * swing16 / kmax, 100 * swing10 / kmax))
assert(drift <= 0.01 * kmax, "energy drift above 1 % at 1.6 dt_c")
assert(swing16 <= 1.25 * swing10, "the energy oscillation grows with the time step")

-- 1.7 dt_c: unstable; the energy grows without bound before the run stops
local rec17, ok17, err17 = run(1.7, 5 * T)
local tot17 = rec17:column("total")
local grown = math.abs(tot17[#tot17] - tot17[1])
print(string.format("V1 1.7 dt_c: %s after %d samples, |E - E0| = %.4g (%.0fx the largest "
  .. "kinetic energy at 1.6 dt_c)", ok17 and "ran through" or "stopped", #tot17, grown, grown / kmax))
assert(not ok17 and tostring(err17):find("simulation failed"),
       "the run at 1.7 dt_c should blow up, as [M] Fig 6b shows")
assert(grown > kmax, "at 1.7 dt_c the energy should have grown clearly before the stop")
