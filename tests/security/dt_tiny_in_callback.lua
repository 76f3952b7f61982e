-- expect: 2
-- stderr: dt_tiny_in_callback\.lua:12: sim:run: dt = 1e-300, set at t = 0\.005, leaves 5e\+297 steps to t_end = 0\.01 \(at most 1e\+12\)
-- Issue 31, item 4: s.dt = 1e-300 in a callback escaped the step cap that
-- sim:run applies at its call (1e12 steps) and the run went on ~for ever.
-- The cap is applied again whenever a callback changes dt; the records up
-- to then are kept.
local sim = lamina.sim{ dt = 1e-3, domain = {0, 0, 1, 1}, cell = 0.1 }
local el = lamina.elastic{ rho = 1000, E = 1000, nu = 0.3 }
sim:body{ material = el, region = lamina.disk{ center = {0.5, 0.5}, radius = 0.2 } }
sim:record{ file = "out/security/dt_tiny.csv", energy = true }
sim:at(0.005, function(s) s.dt = 1e-300 end)
sim:run{ t_end = 0.01 }
