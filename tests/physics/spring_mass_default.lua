-- Issue 30 item 2: [M] §3.1.1's kind of spring-mass on lamina's defaults
-- (quadratic B-spline, segment forces, MUSL). A wire of length L = 0.4
-- hangs from a fixed top wall, A = thickness 0.1, E = 1e6, rho = 0.1,
-- nu = 0, its last point a heavy mass m = 5 (end_mass), g = 100, cell 0.1:
-- k = AE/L = 2.5e5, small-strain period 2 pi sqrt(m/k) = 0.028099, static
-- deflection m g / k = 0.002.
-- The wire's mass rho A L = 0.004 is 8e-4 of m: a bar with an end mass has
-- omega L/c tan(omega L/c) = m_bar/m, i.e. m + m_bar/3 to within
-- (m_bar/m)^2; kept as the reference's mass (+0.013 % on the period).
-- The exact answer for lamina's law: the tension is E A ln(l/L0) (the
-- logarithmic strain, membrane_force.c), so the spring softens as it
-- stretches: (m + m_bar/3) u'' = m g - E A ln(1 + u/L), u(0) = u'(0) = 0
-- (the mass starts at rest at the unstretched length). Integrated here with
-- RK4 at T/20000: period 0.028172 (+0.26 % from the small-strain one),
-- mean deflection 0.0020080 (+0.40 %).
-- Before (src/mpm/constraint.c): the heavy point's mass lumped over its
-- stencil carried the wire's neighbouring points: period -9.0 % at 3
-- points a cell, -8.3 % at 1, -4.5 % at cell 0.05, -2.4 % at 0.025.
-- Measured now (period, mean deflection from the reference): 3 points a
-- cell -0.00 % / +0.01 %, 1 point a cell -0.00 % / +0.00 %, cell 0.05 -0.00 %
-- / +0.01 % (converged: the heavy point no longer carries its neighbours);
-- total energy (the heavy point's kinetic energy and gravity work in it)
-- within 0.18 % / 0.18 % / 0.09 % of the largest kinetic energy, asserted 1 %.
-- On main 2368986 the same script gave -11.4 % / +5.0 % at 3 points a cell.
-- The papers' scheme (linear, point forces, the heavy point lumped as in
-- [M]; scripts/paper keep their numbers): period -0.74 %, asserted within
-- 1 %; its mean deflection -1.10 % is printed, not asserted (a known miss of
-- the papers' scheme, not of the default this item is about).
local E, A, rho, L, m, g = 1e6, 0.1, 0.1, 0.4, 5, 100
local mb = rho * A * L

-- the reference: RK4 on the log-strain oscillator over 6 periods
local function reference()
  local M = m + mb / 3
  local T0 = 2 * math.pi * math.sqrt(M * L / (E * A))
  local h = T0 / 20000
  local function acc(u) return g - E * A * math.log(1 + u / L) / M end
  local u, v, t = 0, 0, 0
  local ts, us = {0}, {0}
  while t < 6 * T0 do
    local k1u, k1v = v, acc(u)
    local k2u, k2v = v + 0.5 * h * k1v, acc(u + 0.5 * h * k1u)
    local k3u, k3v = v + 0.5 * h * k2v, acc(u + 0.5 * h * k2u)
    local k4u, k4v = v + h * k3v, acc(u + h * k3u)
    u = u + h / 6 * (k1u + 2 * k2u + 2 * k3u + k4u)
    v = v + h / 6 * (k1v + 2 * k2v + 2 * k3v + k4v)
    t = t + h
    ts[#ts + 1], us[#us + 1] = t, u
  end
  return ts, us
end

-- period from the upward crossings of the level c (the small-strain static
-- deflection), mean over whole periods
local function period_mean(ts, us)
  local c = m * g * L / (E * A)
  local up = {}
  for i = 2, #ts do
    local a, b = us[i - 1] - c, us[i] - c
    if a < 0 and b >= 0 then up[#up + 1] = ts[i - 1] + (ts[i] - ts[i - 1]) * (-a) / (b - a) end
  end
  assert(#up >= 4, "expected 4 or more upward crossings, got " .. #up)
  local s, n = 0, 0
  for i = 1, #ts do
    if ts[i] >= up[1] and ts[i] < up[#up] then s, n = s + us[i], n + 1 end
  end
  return (up[#up] - up[1]) / (#up - 1), s / n
end

local Tref, dref = period_mean(reference())

local function run(ppc, h, basis, force)
  local sim = lamina.sim{ basis = basis, domain = {0, 0, 0.4, 1.0}, cell = h,
                          dt = 0.5 * h / math.sqrt(E / rho), gravity = {0, -g},
                          boundary = { left = "free", right = "free", bottom = "free", top = "fixed" } }
  local wire = lamina.membrane{ rho = rho, E = E, nu = 0, thickness = A, law = "uniaxial" }
  local s = sim:membrane{ force = force, material = wire, count = math.floor(L / h * ppc + 0.5) + 1,
                          end_mass = m, curve = lamina.segment{ from = {0.2, 1.0}, to = {0.2, 1.0 - L} } }
  local rec = sim:record{ every = sim.dt, energy = true, points = { mass = {s, -1} } }
  sim:run{ t_end = 6 * Tref }
  local ts, ys = rec:column("t"), rec:column("mass_y")
  local us = {}
  for i = 1, #ys do us[i] = (1.0 - L) - ys[i] end
  local T, d = period_mean(ts, us)
  local eT, ed = T / Tref - 1, d / dref - 1
  print(string.format("%-8s %-7s %d points a cell, cell %-5g: period %.6f (%+.2f %%), mean deflection "
    .. "%.7f (%+.2f %%); reference %.6f, %.7f", sim.basis, force or "segment", ppc, h, T, 100 * eT, d, 100 * ed,
    Tref, dref))
  -- energy: the heavy point's kinetic energy and gravity work included
  local kin, tot = rec:column("kinetic"), rec:column("total")
  local kmax, swing = 0, 0
  for i = 1, #kin do
    kmax = math.max(kmax, kin[i])
    swing = math.max(swing, math.abs(tot[i] - tot[1]))
  end
  print(string.format("  total energy within %.3f %% of the largest kinetic energy", 100 * swing / kmax))
  return eT, ed, swing / kmax
end

for _, c in ipairs{ {3, 0.1}, {1, 0.1}, {3, 0.05} } do
  local eT, ed, de = run(c[1], c[2], nil, nil)
  assert(de < 0.01, string.format("default: energy changed by %.2f %% of the largest KE", 100 * de))
  assert(math.abs(eT) < 0.01, string.format("default: period off by %.2f %%", 100 * eT))
  assert(math.abs(ed) < 0.01, string.format("default: deflection off by %.2f %%", 100 * ed))
end
local eT = run(3, 0.1, "linear", "point")
assert(math.abs(eT) < 0.01, string.format("papers' scheme: period off by %.2f %%", 100 * eT))
