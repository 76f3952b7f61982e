-- expect: 2
-- stderr: nested_run\.lua:8: sim:run/sim:step called from inside a callback
-- A callback that tries to run the simulation it is called from.
local sim = lamina.sim{ dt = 1e-3 }
local m = lamina.elastic{ rho = 1, E = 1, nu = 0.3 }
sim:body{ material = m, region = lamina.disk{ center = {0.5, 0.5}, radius = 0.2 } }
sim:every(0.01, function(s)
  s:run{ t_end = 1 }
end)
sim:run{ t_end = 0.1 }
