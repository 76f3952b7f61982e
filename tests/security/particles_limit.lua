-- expect: 2
-- stderr: particles_limit\.lua:10: sim:body: the region's cells at ppc = 4096 hold 4096000000 trial points, more than the limit of 200000000
-- Issue 18, memory: no particle limit (ppc = 4096 on a 1000 x 1000 grid is
-- 4e9 particles). Refused before any is made; the total per simulation is
-- capped too (5e7, five times the 10^7-particle benchmark).
local sim = lamina.sim{ dt = 1e-3, cell = 0.001 }
local el = lamina.elastic{ rho = 1000, E = 1000, nu = 0.3 }
local ok, err = pcall(sim.body, sim, { material = el, ppc = 4096, region = function() return false end })
assert(not ok and err:find("4096000000 trial points"), tostring(err))
sim:body{ material = el, ppc = 4096, region = lamina.rect{ min = {0, 0}, max = {1, 1} } }
