-- expect: 1
-- stderr: the run stopped: simulation failed: at t = 0\.001
-- A failure caught and raised again is still the simulation's (status 1).
local sim = lamina.sim{ dt = 1e-3, domain = {0, 0, 1, 1}, cell = 0.05 }
local el = lamina.elastic{ rho = 1000, E = 1000, nu = 0.3 }
sim:body{ material = el, region = lamina.disk{ center = {0.5, 0.5}, radius = 0.2 },
          velocity = {1e3, 0} }
local ok, err = pcall(sim.run, sim, { t_end = 1 })
error("the run stopped: " .. err, 0)
