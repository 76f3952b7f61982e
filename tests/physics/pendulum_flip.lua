-- Issue 13 item 6: the pendulum of [T] §5.7 (L 0.73, end mass 3.3, g 20,
-- theta0 19.8 deg, rho 0.1, t 0.1, E 1e6, one-way law) with NO PIC blend,
-- its tension integrated along segments (force = "segment"), at cells 0.05
-- and 0.025: it runs to t = 2, the string's length stays within 3 % of
-- 0.73, and its rms angle error against the bar-element FEM (ours,
-- assets/lua/barfem.lua; t <= 1.8) is no worse than the papers' scheme as
-- the gallery runs it today (point quadrature with a 0.1 % PIC blend and
-- the papers' point counts, 80 and 320; scripts/paper/membrane_pendulum.lua),
-- computed here beside it. The segments' points are about 3/4 of a cell
-- apart (20 and 40 points): the segment form damps the swing more the more
-- points a cell holds (cell 0.05, no PIC: 20 points 0.255 deg, 30 0.597,
-- 40 0.826, 80 1.034, 160 1.264; docs/robustness.md "The pendulum
-- without a PIC blend"), so it is asserted at 3/4 of a cell and the papers'
-- 80 points are printed. With point quadrature and no PIC the string tears
-- (printed).
local barfem = require("barfem")
local E, L, m, g, th0, rho, t = 1e6, 0.73, 3.3, 20, 19.8, 0.1, 0.1
local c = math.sqrt(E / rho)
local px, py = 0.6, 1.0
local mx, my = px + L * math.sin(math.rad(th0)), py - L * math.cos(math.rad(th0))
local fem = barfem.run{ from = {px, py}, to = {mx, my}, elements = 20, rho = rho, A = t, E = E,
                        end_mass = m, g = {0, -g}, one_way = true, t_end = 2.0,
                        every = 1e-3, safety = 0.9 }

local function run(h, n, force, pic, t_end, basis)
  local sim = lamina.sim{ basis = basis or "linear", domain = {0, 0, 1.2, 1.0}, cell = h, dt = 0.63 * h / c,
                          gravity = {0, -g}, pic = pic }
  local wire = lamina.membrane{ rho = rho, E = E, nu = 0, thickness = t, one_way = true }
  local s = sim:membrane{ material = wire, count = n, end_mass = m, name = "string", force = force,
                          curve = lamina.segment{ from = {px, py}, to = {mx, my} } }
  local rec = sim:record{ every = 1e-3, angle = { theta = s } }
  local dl = 0
  sim:every(1e-3, function()
    local q, len = s:particles(), 0
    for i = 2, #q.x do len = len + math.sqrt((q.x[i] - q.x[i - 1])^2 + (q.y[i] - q.y[i - 1])^2) end
    dl = math.max(dl, math.abs(len / L - 1))
  end)
  local ok, err = pcall(sim.run, sim, { t_end = t_end })
  local ts, th = rec:column("t"), rec:column("theta")
  local se, n18 = 0, 0
  for i = 1, #ts do
    if ts[i] <= 1.8 + 1e-9 then
      se = se + (th[i] - barfem.at(fem.t, fem.theta, ts[i]))^2
      n18 = n18 + 1
    end
  end
  return ok, err, math.sqrt(se / math.max(n18, 1)), dl, sim.t
end

local today = { [0.05] = 80, [0.025] = 320 }     -- the gallery's point counts
local today_rms = {}
for _, c in ipairs{ {0.05, 20}, {0.025, 40} } do
  local h, n = c[1], c[2]
  local ok, err, rms, dl, tt = run(h, n, "segment", 0, 2.0)
  print(string.format("cell %.3f, %d points (%.2f cells apart), segment, no PIC: %s to t = %.3f, "
                      .. "rms theta error (t <= 1.8) %.3f deg, length within %.2f %%", h, n,
                      L / (n - 1) / h, ok and "ran" or "FAILED", tt, rms, 100 * dl))
  assert(ok, err)
  assert(dl < 0.03, string.format("string length changed by %.2f %% (limit 3 %%)", 100 * dl))
  local ok2, err2, rms2 = run(h, today[h], "point", 0.001, 1.8)
  print(string.format("cell %.3f, %d points, point quadrature + PIC 0.001 (today's gallery): "
                      .. "rms %.3f deg", h, today[h], rms2))
  assert(ok2, err2)
  today_rms[h] = rms2
  assert(rms <= rms2, string.format("cell %.3f: segment forces without PIC %.3f deg, worse than "
                                    .. "today's %.3f deg", h, rms, rms2))
end

-- lamina's defaults (the quadratic B-spline, segments; basis "bspline2"
-- here), points about a cell apart: its wider stencil wants wider spacing
-- (cell 0.05: 16 points 0.254 deg, 20 1.223, 30 1.632). At cell 0.05 it
-- beats today's blended scheme (asserted); at 0.025 it is on par, not
-- better: 0.24-0.29 deg over 31-34 points against today's 0.242 (printed;
-- docs/robustness.md "Which default").
local okd, errd, rmsd, dld = run(0.05, 16, "segment", 0, 2.0, "bspline2")
print(string.format("cell 0.050, 16 points, defaults (bspline2, segment), no PIC: rms %.3f deg, "
                    .. "length within %.2f %%", rmsd, 100 * dld))
assert(okd, errd)
assert(dld < 0.03, string.format("defaults: length changed by %.2f %%", 100 * dld))
assert(rmsd <= today_rms[0.05], string.format("defaults at cell 0.05: %.3f deg, today's %.3f",
                                               rmsd, today_rms[0.05]))
-- The runs below assert nothing: they measure what docs/robustness.md
-- quotes ("Which default", "The pendulum without a PIC blend"). They take
-- over half of this test's time, so the test command leaves them out;
-- `lamina run tests/physics/pendulum_flip.lua --set measure=1` prints them.
if lamina.param("measure", 0) == 0 then return end
for _, n in ipairs{31, 33} do
  local _, _, r25 = run(0.025, n, "segment", 0, 1.8, "bspline2")
  print(string.format("cell 0.025, %d points, defaults, no PIC: rms %.3f deg (today's %.3f)", n, r25,
                      today_rms[0.025]))
end

-- the papers' 80 points at cell 0.05 with segments (printed: more damped)
local _, _, rms80 = run(0.05, 80, "segment", 0, 1.8)
print(string.format("cell 0.050, 80 points, segment, no PIC: rms %.3f deg", rms80))
local ok3, err3 = run(0.05, 80, "point", 0, 2.0)
print("cell 0.05, point quadrature, no PIC: " .. (ok3 and "ran" or err3:match("tore[^;]*") or err3))
