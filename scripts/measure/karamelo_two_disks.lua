-- The two elastic disks of scripts/measure/karamelo_two_disks.mpm in lamina
-- (issue 36 item 5, docs/performance.md "Karamelo"): cell 0.005, 4 points a
-- cell, linear basis, USL, dt 1e-3, 300 steps, no output but the energy.
-- Timed whole, beside Karamelo: /usr/bin/time lamina run THIS
--   (--set basis=bspline2 for lamina's default basis)
local basis = lamina.param("basis", "linear")
local sim = lamina.sim{ domain = {0, 0, 1, 1}, cell = 0.005, dt = 1e-3, scheme = "usl",
                        basis = basis, threads = 1 }
local rubber = lamina.elastic{ rho = 1000, E = 1000, nu = 0.3, plane = "strain" }
sim:body{ material = rubber, ppc = 4, velocity = { 0.1,  0.1},
          region = lamina.disk{ center = {0.25, 0.25}, radius = 0.2 } }
sim:body{ material = rubber, ppc = 4, velocity = {-0.1, -0.1},
          region = lamina.disk{ center = {0.75, 0.75}, radius = 0.2 } }
local c0 = os.clock()
sim:step(300)
local c = os.clock() - c0
print(string.format("%d particles, 300 steps: %.3f s, %.2f M particle-steps/s (CPU), kinetic %.6g",
                    sim.n, c, sim.n * 300 / c / 1e6, sim:energy().kinetic))
