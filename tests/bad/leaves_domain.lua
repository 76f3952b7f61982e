-- expect: 1
-- stderr: simulation failed: at t = 0\.0[0-9]+ \(step [0-9]+\): particle [0-9]+ of body 2 left the domain
-- stderr: likely cause
-- A body flying out through a free side stops the run (exit 1) naming the
-- time, step, particle and body.
local sim = lamina.sim{ dt = 1e-3, boundary = "free" }
local m = lamina.elastic{ rho = 1, E = 10, nu = 0.3 }
sim:body{ material = m, region = lamina.disk{ center = {0.3, 0.5}, radius = 0.1 } }
sim:body{ material = m, region = lamina.disk{ center = {0.8, 0.5}, radius = 0.1 },
          velocity = {10, 0} }
sim:run{ t_end = 1 }
