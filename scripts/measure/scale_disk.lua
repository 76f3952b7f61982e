-- scale_disk.lua - issue 17 item 5: does a 10^7-particle run step on this
-- machine, and what does a particle cost in memory? One elastic disk, 4
-- points per cell, cell 1/2000, a few steps, one thread by default.
--   /usr/bin/time -v lamina run scripts/measure/scale_disk.lua --set n=1e7
-- prints the particle count, the seeding and stepping times; the maximum
-- resident set size of `time -v` over the count is the memory per particle
-- (grid included). Measured 2026-12-03 (idle): 10 000 019 particles,
-- grid 1788 x 1788, 2.57 GB (257 bytes a particle), seeding 0.8 s, 3 steps
-- 1.9 s; 10^6: 307 MB (307 bytes) - docs/performance.md "Scale and memory".
local n_target = lamina.param("n", 1e7)
local steps = lamina.param("steps", 3)
local ppc = 4
-- disk area pi r^2 with 4 per cell: cells = n / 4, area = cells h^2
local h = 1 / 2000
local r = math.sqrt(n_target / ppc * h * h / math.pi)
local L = 2 * r + 4 * h
local sim = lamina.sim{ domain = {0, 0, L, L}, cell = h, dt = 0.2 * h / 1.2, basis = "linear",
                        threads = lamina.param("threads", 1) }
local m = lamina.elastic{ rho = 1000, E = 1000, nu = 0.3 }
local c0 = lamina.clock()
local b = sim:body{ material = m, ppc = ppc, velocity = {0.1, 0},
                    region = lamina.disk{ center = {L / 2, L / 2}, radius = r } }
local c1 = lamina.clock()
sim:step(steps)
local c2 = lamina.clock()
print(string.format("particles %d, grid %d x %d, seeding %.1f s, %d steps %.1f s (%.2f M p-steps/s)",
  sim.n, math.floor(L / h + 0.5), math.floor(L / h + 0.5), c1 - c0, steps, c2 - c1, sim.n * steps / (c2 - c1) / 1e6))
