-- Issue 13: segment forces keep the energy of stretch-dominated motion.
-- A free string (no walls near, no gravity, E 1e7, rho 1000, t 0.01,
-- two-way law) released from a uniform strain of 1 % rings lengthwise:
-- its strain energy turns into kinetic energy and back. A mass-spring
-- chain would keep the sum exactly; lamina's segments must too, to the
-- time-stepping error. Before the fix of 2026-12-02 (third session:
-- segment points moved with v^L while FLIP carried the re-mapped velocity,
-- membrane_force.c) this string lost 7.2 % in 0.1 s (0.4 cells apart),
-- 3.7 % at 1 cell, 12 % at 30 degrees; the slack dog-bone lost 14 %.
-- Tolerance 1 %: issue 13 item 6's bound on the trampoline's energy.
-- USL is printed, not asserted: its strain velocity is v^L, and its point
-- form loses the same way (0.82 of the energy here), docs/robustness.md.
local function ring(o)
  local h = 0.05
  local sim = lamina.sim{ domain = {-1, -1, 1, 1}, cell = h, dt = 1e-5, boundary = "free",
                          basis = o.basis, scheme = o.scheme or "musl" }
  local wire = lamina.membrane{ rho = 1000, E = 1e7, thickness = 0.01 }
  local c, s, L = math.cos(math.rad(o.angle)), math.sin(math.rad(o.angle)), 0.8
  -- off the grid lines by a fraction of a cell, so points cross cell edges
  sim:membrane{ material = wire, count = o.n, initial_strain = 0.01, force = "segment",
                curve = lamina.segment{ from = {-L / 2 * c + 0.013, -L / 2 * s + 0.007},
                                        to = {L / 2 * c + 0.013, L / 2 * s + 0.007} } }
  local e0 = sim:energy()
  local worst, smin = 0, e0.strain
  for k = 1, 20 do
    sim:run{ t_end = k * 0.005 }
    local e = sim:energy()
    worst = math.max(worst, math.abs(e.total / e0.total - 1))
    smin = math.min(smin, e.strain)
  end
  return worst, smin / e0.strain
end

for _, o in ipairs{ {basis = "linear", angle = 0, n = 41}, {basis = "linear", angle = 0, n = 17},
                    {basis = "linear", angle = 30, n = 41}, {basis = "gimp", angle = 0, n = 41},
                    {basis = "bspline2", angle = 0, n = 41}, {basis = "bspline2", angle = 30, n = 41} } do
  local worst, smin = ring(o)
  print(string.format("%-8s %2d deg, %d points (%.2f cells apart): energy within %.3f %% over 0.1 s, "
                      .. "strain energy down to %.2f of its start", o.basis, o.angle, o.n,
                      0.8 / (o.n - 1) / 0.05, 100 * worst, smin))
  assert(smin < 0.5, "the string did not ring (strain energy never below half its start)")
  assert(worst < 0.01, string.format("%s at %d deg: energy changed by %.2f %% (limit 1 %%)",
                                     o.basis, o.angle, 100 * worst))
end
local worst = ring{ basis = "linear", angle = 0, n = 41, scheme = "usl" }
print(string.format("usl (not asserted): energy changed by up to %.1f %%", 100 * worst))
