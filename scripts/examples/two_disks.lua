-- Two elastic disks: the classic MPM test (Sulsky, Chen & Schreyer 1994).
-- Source: the standard first test of every MPM code; issue 2 of lamina.
-- What to look for: the disks approach along the diagonal, touch near t = 1,
-- flatten, and bounce apart; total energy stays flat within a few percent
-- and the total momentum stays zero to round-off.
local cell  = lamina.param("cell", 0.05)
local t_end = lamina.param("t_end", 3.0)
local dt    = lamina.param("dt", 1e-3)
local out   = lamina.param("out", "out/two_disks")
local scheme = lamina.param("scheme", "musl")

-- the 1994 paper's bilinear basis (lamina's default is the quadratic
-- B-spline, docs/api.md)
local sim = lamina.sim{ domain = {0, 0, 1, 1}, cell = cell, dt = dt, scheme = scheme, basis = "linear" }
local rubber = lamina.elastic{ rho = 1000, E = 1000, nu = 0.3, plane = "strain" }
local a = sim:body{ material = rubber, ppc = 4, velocity = { 0.1,  0.1},
                    region = lamina.disk{ center = {0.25, 0.25}, radius = 0.2 }, name = "lower" }
local b = sim:body{ material = rubber, ppc = 4, velocity = {-0.1, -0.1},
                    region = lamina.disk{ center = {0.75, 0.75}, radius = 0.2 }, name = "upper" }

local e0 = sim:energy().total
local emin, emax = e0, e0
sim:every(0.1, function(s)
  local e = s:energy().total
  emin, emax = math.min(emin, e), math.max(emax, e)
  s:frame{ file = string.format("%s/frame_%06d.png", out, s.nstep), width = 512, height = 512 }
end)
sim:run{ t_end = t_end }

local px, py = sim:momentum()
local e = sim:energy()
print(string.format("t = %.3f  steps = %d  particles = %d", sim.t, sim.nstep, sim.n))
print(string.format("energy: start %.6g  end %.6g  (min %.6g, max %.6g; drift %.2f %%)",
                    e0, e.total, emin, emax, 100 * (e.total - e0) / e0))
print(string.format("momentum: (%.3g, %.3g)", px, py))
print(string.format("lower disk velocity: (%.4f, %.4f)", a:velocity()))
print(string.format("upper disk velocity: (%.4f, %.4f)", b:velocity()))
