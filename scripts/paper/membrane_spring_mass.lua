-- title: Spring-mass: a string of membrane points holding a heavy point
-- source: York, Sulsky & Schreyer 1999 (membranes), §3.1.1, Figs 5 and 6
-- look: the end mass oscillates between 0 and 0.005 below its start, on top
--   of the dashed analytic curve; the energy stays flat at dt_c and 1.6 dt_c
--   and runs away at 1.7 dt_c (the run stops when a point inverts)
-- checks: period 2 pi sqrt(mL/(AE)) = 0.01987 and static deflection
--   mgL/(AE) = 0.0025 against the MPM's; energy drift at 1.6 dt_c
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

local function run(factor, frames)
  local sim = lamina.sim{ basis = "linear", domain = {0, 0, 0.2, 2.0}, cell = h, dt = factor * dtc,
                          gravity = {0, g}, courant = 1.8,
                          boundary = { left = "symmetry", right = "symmetry" } }
  local wire = lamina.membrane{ rho = rho, E = E, nu = 0, thickness = A, law = "uniaxial" }
  local s = sim:membrane{ force = "point", material = wire, count = 10, end_mass = m, name = "spring",
                          curve = lamina.segment{ from = {0.1, 1.99}, to = {0.1, 1.69} } }
  local rec = sim:record{ every = dtc, energy = true, points = { mass = {s, -1} },
                          file = string.format("%s/history_%.1f.csv", out, factor) }
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
local up = {}
for i = 2, #t10 do
  local a, b = d10[i - 1] - d_static, d10[i] - d_static
  if a < 0 and b >= 0 then up[#up + 1] = t10[i - 1] + (t10[i] - t10[i - 1]) * (-a) / (b - a) end
end
local period = #up >= 2 and (up[#up] - up[1]) / (#up - 1) or 0
local mean = #up >= 2 and 1.69 - rec10:mean("mass_y", up[1], up[#up]) or 0
local kmax = 0
for _, v in ipairs(rec16:column("kinetic")) do kmax = math.max(kmax, v) end
local drift = periods >= 2 and math.abs(rec16:mean("total", (periods - 1) * T, periods * T)
                                         - rec16:mean("total", 0, T)) / kmax or 0
print(string.format("period %.6f (analytic %.6f), mean deflection %.6f (analytic %.6f), "
  .. "energy drift at 1.6 dt_c %.4f %% of max KE, 1.7 dt_c %s", period, T, mean, d_static,
  100 * drift, ok17 and "ran" or "blew up"))
lamina.report{
  period = { period, ref = T, unit = "s", tol = 0.02 * T },
  deflection = { mean, ref = d_static, tol = 0.05 * d_static },
  drift_16 = { 100 * drift, unit = "% of max KE" },
  unstable_17 = not ok17,
  -- the three time steps' states (assets/lua/hashes.lua)
  state_hash = require("hashes").fold{ sim10:hash(), sim16:hash(), sim17:hash() },
}
