-- title: Spring-mass: a string of membrane points holding a heavy point
-- source: York, Sulsky & Schreyer 1999 (membranes), §3.1.1, Figs 5 and 6
-- look: the end mass oscillates between 0 and 0.005 below its start, on top
--   of the dashed analytic curve; the energy stays flat at dt_c and 1.6 dt_c
--   and runs away at 1.7 dt_c (the run stops when a point inverts)
-- checks: period 2 pi sqrt(mL/(AE)) = 0.01987 and static deflection
--   mgL/(AE) = 0.0025 against the MPM's, at the paper's g and at g / 100;
--   energy drift at 1.6 dt_c. The tolerances ([M] says only "compares
--   favourably") are what the closed forms leave out of this string, computed
--   in the page: they are a linear, massless spring's. (a) Finite strain: the
--   string's tension as the grid stretches it is AE eps exp(eps), eps = x / L
--   (the grid's velocity field runs from the node by the mass to the wall, a
--   fixed length, so the points accumulate the engineering strain; their
--   volume is t ds exp(eps), src/mpm/membrane.c); at [M]'s g the strain
--   reaches 2 mg / (AE) = 1.7 %, and the heavy point on that tension
--   (integrated here by RK4) swings with a period 0.82 % shorter and about a
--   mean deflection 1.23 % smaller than the closed forms'. (b) The string's
--   own mass m_s = 9 rho A ds = 0.003: the period + m_s / (6 m), the
--   deflection + m_s / (2 m). Tolerance |a| + |b|: 0.83 % and 1.27 % at [M]'s
--   g, 0.023 % and 0.059 % at g / 100, where the strain is 0.017 % and the
--   closed forms hold (it was 2 % and 5 %, not derived; refining the cell
--   does not converge the miss, -0.81 / -0.81 / +1.13 % at cells 0.1 / 0.05 /
--   0.025, while lowering g does: -0.81 / -0.07 / +0.006 % at g, g / 10,
--   g / 100: the miss is the amplitude's, not the grid's)
-- assumed: the string on the node line x = 0.1 of a 0.2-wide column with
--   symmetry walls (the paper does not draw the domain); point mass
--   rho A ds with ds = L/9, so the end mass is 10 000x the others as in [M]
-- visual: periods=1
-- thumb: fig6a_displacement.png
local out = lamina.param("out", "out/membrane_spring_mass")
local periods = lamina.param("periods", 5)

local E, A, rho, L, m, g, h = 1e6, 0.1, 0.1, 0.3, 3.33, -250, 0.1
local dtc = h / math.sqrt(E / rho)
local k = A * E / L
local omega = math.sqrt(k / m)
local T = 2 * math.pi / omega
local d_static = m * -g / k

local function run(factor, frames, gscale)
  local sim = lamina.sim{ basis = "linear", domain = {0, 0, 0.2, 2.0}, cell = h, dt = factor * dtc,
                          gravity = {0, g * (gscale or 1)}, courant = 1.8,
                          boundary = { left = "symmetry", right = "symmetry" } }
  local wire = lamina.membrane{ rho = rho, E = E, nu = 0, thickness = A, law = "uniaxial" }
  local s = sim:membrane{ force = "point", material = wire, count = 10, end_mass = m, name = "spring",
                          curve = lamina.segment{ from = {0.1, 1.99}, to = {0.1, 1.69} } }
  local rec = sim:record{ every = dtc, energy = true, points = { mass = {s, -1} },
                          file = gscale and string.format("%s/history_g%g.csv", out, gscale)
                                 or string.format("%s/history_%.1f.csv", out, factor) }
  if frames then
    sim:frame{ file = out .. "/setup.png", width = 240, height = 800,
               window = {0, 1.4, 0.2, 2.03}, discs = "spacing", title = "Fig 5(b): t = 0" }
  end
  local ok = pcall(sim.run, sim, { t_end = periods * T })
  return rec, ok, sim
end

local rec10, _, sim10 = run(1.0, true)
local rec16, _, sim16 = run(1.6)
local rec17, ok17, sim17 = run(1.7)
local small = 0.01   -- g / 100: strain 0.017 %, where the closed forms hold
local rec_s, _, sim_s = run(1.0, false, small)

-- Fig 6(a): displacement of the mass against d_s (1 - cos omega t)
local function disp(rec)
  local t, y = rec:column("t"), rec:column("mass_y")
  local d = {}
  for i = 1, #y do d[i] = 1.69 - y[i] end
  return t, d
end
local t10, d10 = disp(rec10)
local t16, d16 = disp(rec16)
local exact = {}
for i = 1, #t10 do exact[i] = d_static * (1 - math.cos(omega * t10[i])) end
lamina.plot{ file = out .. "/fig6a_displacement.png", csv = true,
             title = "Fig 6(a): displacement of the mass", xlabel = "t", ylabel = "displacement",
             series = { { x = t10, y = d10, label = "MPM, dt = dt_c" },
                        { x = t16, y = d16, label = "MPM, dt = 1.6 dt_c" },
                        { x = t10, y = exact, label = "analytic", dashed = true, color = 8 } } }

-- Fig 6(b): total energy at three time steps
local e17t, e17 = rec17:column("t"), rec17:column("total")
lamina.plot{ file = out .. "/fig6b_energy.png", csv = true,
             title = "Fig 6(b): total energy", xlabel = "t", ylabel = "energy",
             yrange = {-0.5, 1.5},
             series = { { x = rec10:column("t"), y = rec10:column("total"), label = "dt_c" },
                        { x = rec16:column("t"), y = rec16:column("total"), label = "1.6 dt_c" },
                        { x = e17t, y = e17, label = "1.7 dt_c (blows up)" } } }

-- measured period (upward crossings of the static deflection) and mean
local function measure(rec, d_s)
  local t, y = rec:column("t"), rec:column("mass_y")
  local up = {}
  for i = 2, #t do
    local a, b = 1.69 - y[i - 1] - d_s, 1.69 - y[i] - d_s
    if a < 0 and b >= 0 then up[#up + 1] = t[i - 1] + (t[i] - t[i - 1]) * (-a) / (b - a) end
  end
  if #up < 2 then return 0, 0 end
  return (up[#up] - up[1]) / (#up - 1), 1.69 - rec:mean("mass_y", up[1], up[#up])
end
local period, mean = measure(rec10, d_static)
local period_s, mean_s = measure(rec_s, small * d_static)

-- What the closed forms leave out (the header's (a) and (b)): (a) the heavy
-- point on the string's finite-strain tension AE eps exp(eps), eps = x / L,
-- released from rest at x = 0 (RK4, 20 000 steps a period): its period
-- (successive deepest points) and its mean deflection over one period,
-- relative to the closed forms'; (b) the string's own mass.
local function finite_strain(gs)
  local gg, T0, d0 = -g * gs, T, d_static * gs
  local function acc(x) local e = x / L; return gg - k * L * e * math.exp(e) / m end
  local x, v, t, dt = 0, 0, 0, T0 / 20000
  local deep, sum, span = {}, 0, 0
  while #deep < 2 and t < 3 * T0 do
    local k1x, k1v = v, acc(x)
    local k2x, k2v = v + dt / 2 * k1v, acc(x + dt / 2 * k1x)
    local k3x, k3v = v + dt / 2 * k2v, acc(x + dt / 2 * k2x)
    local k4x, k4v = v + dt * k3v, acc(x + dt * k3x)
    local xn = x + dt / 6 * (k1x + 2 * k2x + 2 * k3x + k4x)
    local vn = v + dt / 6 * (k1v + 2 * k2v + 2 * k3v + k4v)
    if v > 0 and vn <= 0 then deep[#deep + 1] = t + dt * v / (v - vn) end
    if #deep == 1 then sum, span = sum + 0.5 * (x + xn) * dt, span + dt end
    x, v, t = xn, vn, t + dt
  end
  return (deep[2] - deep[1]) / T0 - 1, sum / span / d0 - 1
end
local ms = rho * A * L                 -- the nine light points, rho A ds each (ds = L / 9)
local mass_T, mass_d = ms / (6 * m), ms / (2 * m)
local fsT, fsd = finite_strain(1)
local fsT_s, fsd_s = finite_strain(small)
local tolT, told = math.abs(fsT) + mass_T, math.abs(fsd) + mass_d
local tolT_s, told_s = math.abs(fsT_s) + mass_T, math.abs(fsd_s) + mass_d
local kmax = 0
for _, v in ipairs(rec16:column("kinetic")) do kmax = math.max(kmax, v) end
local drift = periods >= 2 and math.abs(rec16:mean("total", (periods - 1) * T, periods * T)
                                         - rec16:mean("total", 0, T)) / kmax or 0
print(string.format("period %.6f (analytic %.6f, %+.3f %%; finite strain %+.3f %%, string mass %+.3f %%), "
  .. "mean deflection %.6f (analytic %.6f, %+.3f %%; finite strain %+.3f %%, string mass %+.3f %%), "
  .. "energy drift at 1.6 dt_c %.4f %% of max KE, 1.7 dt_c %s", period, T, 100 * (period / T - 1),
  100 * fsT, 100 * mass_T, mean, d_static, 100 * (mean / d_static - 1), 100 * fsd, 100 * mass_d,
  100 * drift, ok17 and "ran" or "blew up"))
print(string.format("at g / 100: period %+.4f %% (finite strain %+.4f %%), deflection %+.4f %% (finite strain %+.4f %%)",
  100 * (period_s / T - 1), 100 * fsT_s, 100 * (mean_s / (small * d_static) - 1), 100 * fsd_s))
lamina.report{
  -- tolerances: the header's (a) + (b), computed above (they were 2 % and
  -- 5 %, not derived)
  period = { period, ref = T, unit = string.format("s (tol: finite strain %.2f %% + string mass %.3f %%)",
             100 * math.abs(fsT), 100 * mass_T), tol = tolT * T },
  deflection = { mean, ref = d_static, unit = string.format("(tol: finite strain %.2f %% + string mass %.3f %%)",
                 100 * math.abs(fsd), 100 * mass_d), tol = told * d_static },
  period_g100 = { period_s, ref = T, unit = string.format("s at g / 100 (tol: finite strain %.4f %% + string mass %.3f %%)",
                  100 * math.abs(fsT_s), 100 * mass_T), tol = tolT_s * T },
  deflection_g100 = { mean_s / small, ref = d_static, unit = string.format("(at g / 100, times 100; tol: finite strain %.4f %% + string mass %.3f %%)",
                      100 * math.abs(fsd_s), 100 * mass_d), tol = told_s * d_static },
  period_finite_strain = { T * (1 + fsT), unit = "s (ours: the heavy point on AE eps exp(eps), RK4)" },
  deflection_finite_strain = { d_static * (1 + fsd), unit = "(ours: mean over a period, the same oscillator)" },
  drift_16 = { 100 * drift, unit = "% of max KE" },
  unstable_17 = not ok17,
  -- the three time steps' states (assets/lua/hashes.lua)
  state_hash = require("hashes").fold{ sim10:hash(), sim16:hash(), sim17:hash(), sim_s:hash() },
}
