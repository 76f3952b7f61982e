-- expect: 2
-- stderr: caught_failure_then_mistake\.lua:11: lamina\.sim: unknown key 'dtt'
-- Issue 18, wrong answers: after a caught run failure, an unknown key exited
-- with status 1 (the simulation failed) instead of 2 (the script is wrong).
local sim = lamina.sim{ dt = 1e-3, domain = {0, 0, 1, 1}, cell = 0.05 }
local el = lamina.elastic{ rho = 1000, E = 1000, nu = 0.3 }
sim:body{ material = el, region = lamina.disk{ center = {0.5, 0.5}, radius = 0.2 },
          velocity = {1e3, 0} }
local ok, err = pcall(sim.run, sim, { t_end = 1 })
assert(not ok and err:find("simulation failed"), tostring(err))
lamina.sim{ dtt = 1 }
