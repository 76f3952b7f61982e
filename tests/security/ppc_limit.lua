-- expect: 2
-- stderr: ppc_limit\.lua:10: sim:body: ppc = 8100 is more than the limit of 4096 points per cell
-- Issue 18, unclear messages: the limit on particles per cell (4096) was
-- not named: ppc = 8100 (a square) was called "not a square number".
local sim = lamina.sim{ dt = 1e-3 }
local el = lamina.elastic{ rho = 1000, E = 1000, nu = 0.3 }
local ok, err = pcall(sim.body, sim, { material = el, ppc = {128, 64},
                      region = lamina.disk{ center = {0.5, 0.5}, radius = 0.2 } })
assert(not ok and err:find("8192 points per cell, more than the limit of 4096"), tostring(err))
sim:body{ material = el, ppc = 8100, region = lamina.disk{ center = {0.5, 0.5}, radius = 0.2 } }
