-- Issue 36 item 1: the gas beside the membranes in the sub-steps' fast group,
-- lamina.sim{substeps = k, fast_band = w} (src/mpm/subcycle_gasband.c;
-- docs/performance.md "The gas beside the membranes in the fast group"). Every
-- gas point whose stencil comes within w cells of a node a membrane point's
-- stencil reaches takes the k sub-steps with the membranes (its force in
-- their sums, its move, re-map and stress every sub-step), so that no node a
-- membrane touches carries the gas's held force and the groups meet inside
-- the gas (spatial subcycling, Belytschko, Yen & Mullen 1979). `--set
-- multirate=...` runs it with another form (default "held"; the "impulse"
-- run is physics.substeps_band_gas_impulse). What it must hold:
-- 1. k = 1 is the plain step, USL and MUSL (the gas in the band only moves
--    from the slow group's update to the sub-step's, the same operations):
--    radius and hoop to 1e-9 (as tests/physics/substeps.lua).
-- 2. The gas-filled quarter circle of tests/physics/substeps.lua in
--    equilibrium (cell 0.1, p = 1000, sigma t = p r at the start), 4 and 10
--    sub-steps, fast_band 0 and 1: radius within 0.2 % and hoop within 1 %
--    over 0.05 s, sigma t = p r within 1 % at the end, no gas out, the total
--    energy within max(1e-5, twice the plain step's change).
-- 3. The same circle started slack, ringing, on cell 0.05 (181 membrane
--    points, 1 291 gas points; the band a strict part of the gas), 10
--    sub-steps, fast_band = 0, to t = 0.5 (the total energy every 0.01): its
--    least-squares trend within 0.05 % of the start's and within twice the
--    plain MUSL step's (the plain step at dt / 10 run here as the reference),
--    every sample within twice the plain step's largest change; the
--    sub-steps without the band, run beside it, must drift by more than
--    five times the plain step's trend (that the check tells them apart).
-- 4. Deterministic: the same run twice, the same hash.
-- Measured 2026-12-05 (held): 1. equal to the 12 digits printed; 2. hoop
-- 0.0558 % (4, w 0), 0.0563 % (10, w 0), 0.0558 % (10, w 1) against the
-- plain step's 0.0556 %; 3. trend plain -0.0016 %, band -0.0016 % (largest
-- 0.0040 % against 0.0041 %; -0.0006 % before the far nodes took the plain
-- step's displacement, subcycle_gasband.c), without the band +0.0363 %;
-- 713 of 1 291 gas points fast. impulse (the expected failure physics.substeps_band_gas_impulse):
-- 2. with 4 sub-steps, fast_band 0, hoop 0.231 % but the energy +1.29e-5 of
-- itself (limit 1e-5; plain 2.1e-9; the kick's offset, first order in dt);
-- 10 sub-steps, fast_band 1: hoop 0.154 % (without the band 45 %,
-- substeps_impulse_equilibrium.lua); 3. trend +0.047 %, largest +0.054 %.
local cm = require("circle_membrane")
local form = lamina.param("multirate", "held")
-- `--set ringing=0` leaves out part 3, the three runs on cell 0.05 to t = 0.5
-- (physics.substeps_band_gas_quick: the code's every line under the
-- sanitizers in a few seconds; the whole test runs in the normal build)
local ringing = lamina.param("ringing", 1) ~= 0
local p0, r, t, E, nu = 1000, 0.5, 0.1, 1e6, 0.3

local function circle(o)
  local sim = lamina.sim{ domain = {0, 0, 1, 1}, cell = o.cell or 0.1, dt = (o.dt0 or 0.5e-4) * (o.k or 1),
                          substeps = o.k, fast_band = o.w, scheme = o.scheme, mass = "lumped",
                          multirate = o.k and form or nil,
                          boundary = { left = "symmetry", bottom = "symmetry", right = "fixed", top = "fixed" } }
  local air = lamina.gas{ rho = 1, p = p0, gamma = 1.4, mu = 0.2 }
  local skin = lamina.membrane{ rho = 0.5, E = E, nu = nu, thickness = t, law = "plane_stress" }
  local gas = sim:body{ material = air, ppc = 16, name = "gas", fill = "clipped",
                        region = lamina.disk{ center = {0, 0}, radius = r } }
  local mem = sim:membrane{ material = skin, count = o.count or 91, name = "membrane", orient = {0, 0},
                            initial_strain = (not o.slack) and p0 * r / t * (1 - nu * nu) / E or nil,
                            curve = lamina.arc{ center = {0, 0}, radius = r, from = 0, to = 90 } }
  local E0 = sim:energy().total
  local ts, es, fast, nf = {}, {}, 0, 0
  sim:every(0.01, function(s)
    ts[#ts + 1] = s.t
    es[#es + 1] = s:energy().total / E0 - 1
    fast, nf = fast + s.fast_gas, nf + 1
  end)
  local drift = cm.watch_drift(sim, mem, r)
  sim:run{ t_end = o.t_end or 0.05 }
  ts[#ts + 1], es[#es + 1] = sim.t, sim:energy().total / E0 - 1
  local wr, ws = drift()
  local trend, worst = cm.energy_trend(ts, es)   -- least-squares slope times the run's length
  local n = #ts
  local beyond, _, grazing = mem:escaped(gas)
  local res = { wr = wr, ws = ws, st = cm.laplace_ratio(mem, gas, t), out = beyond + grazing,
                trend = trend, worst = worst, dE = math.abs(es[n]), hash = sim:hash(),
                r = mem:radius_at(45), hoop = mem:hoop_stress(), fast = nf > 0 and fast / nf or 0, gas = #gas }
  print(string.format("circle%s, cell %g, %s, substeps %s, fast_band %s, %s: radius %.4f %%, hoop %.4f %%, "
    .. "sigma t / p r %.5f, energy: end %+.2e, trend %+.4f %%, largest %.4f %%, gas out %d, fast gas %.0f of %d",
    o.slack and " (slack, ringing)" or "", o.cell or 0.1, o.scheme or "musl", tostring(o.k), tostring(o.w), form,
    100 * wr, 100 * ws, res.st, es[n], 100 * res.trend, 100 * worst, res.out, res.fast, res.gas))
  return res
end

-- 1. one sub-step is the plain step
for _, sc in ipairs{ {"usl", 3e-5}, {"musl", 0.5e-4} } do
  local u0 = circle{ scheme = sc[1], dt0 = sc[2] }
  local u1 = circle{ scheme = sc[1], dt0 = sc[2], k = 1, w = 1 }
  assert(u1.fast > 0, "fast_band = 1: no gas point in the fast group")
  assert(math.abs(u1.r - u0.r) < 1e-9 and math.abs(u1.hoop / u0.hoop - 1) < 1e-9,
         string.format("substeps = 1, fast_band = 1 (%s): radius %.12g vs %.12g, hoop %.12g vs %.12g", sc[1],
                       u1.r, u0.r, u1.hoop, u0.hoop))
end

-- 2. the circle in equilibrium
local c0 = circle{}
for _, kw in ipairs{ {4, 0}, {10, 0}, {10, 1} } do
  local c = circle{ k = kw[1], w = kw[2] }
  local what = string.format("substeps %d, fast_band %d", kw[1], kw[2])
  assert(c.wr < 0.002, string.format("%s: radius moved %.3f %% (limit 0.2 %%)", what, 100 * c.wr))
  assert(c.ws < 0.01, string.format("%s: hoop stress moved %.3f %% (limit 1 %%)", what, 100 * c.ws))
  assert(math.abs(c.st - 1) < 0.01, string.format("%s: sigma t / p r = %.4f", what, c.st))
  assert(c.out == 0, what .. ": gas escaped")
  assert(c.dE <= math.max(1e-5, 2 * c0.dE),
         string.format("%s: energy changed by %.2e (plain %.2e)", what, c.dE, c0.dE))
end

-- 3. ringing, cell 0.05
if ringing then
local fine = { slack = true, t_end = 0.5, cell = 0.05, dt0 = 0.25e-4, count = 181 }
local function with(extra)
  local o = {}
  for key, v in pairs(fine) do o[key] = v end
  for key, v in pairs(extra) do o[key] = v end
  return o
end
local plain = circle(fine)
local bare = circle(with{ k = 10 })
local band = circle(with{ k = 10, w = 0 })
assert(band.fast > 0 and band.fast < band.gas,
       string.format("fast_band = 0: %.0f of %d gas points fast, expected a band", band.fast, band.gas))
assert(math.abs(bare.trend) > 5 * math.abs(plain.trend),
       string.format("without the band: trend %+.4f %%, expected over five times the plain step's %+.4f %%",
                     100 * bare.trend, 100 * plain.trend))
assert(math.abs(band.trend) < 5e-4, string.format("fast_band: energy trend %+.4f %% (limit 0.05 %%)",
                                                  100 * band.trend))
assert(math.abs(band.trend) <= 2 * math.abs(plain.trend),
       string.format("fast_band: energy trend %+.4f %% against the plain step's %+.4f %% (limit twice that)",
                     100 * band.trend, 100 * plain.trend))
assert(band.worst <= 2 * plain.worst,
       string.format("fast_band: energy off by %.4f %% against the plain step's %.4f %% (limit twice that)",
                     100 * band.worst, 100 * plain.worst))
end

-- 4. determinism
assert(circle{ k = 4, w = 1 }.hash == circle{ k = 4, w = 1 }.hash, "two runs with fast_band = 1 differ")
