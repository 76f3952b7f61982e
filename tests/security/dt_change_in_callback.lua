-- expect: 2
-- stderr: dt_change_in_callback\.lua:15: sim\.dt = 1e\+300 is too large: Courant number
-- Issue 18, wrong answers: a dt change in a callback overshot t_end (the
-- step count was fixed when the run began), and s.dt = 1e300 was not
-- Courant-checked. The run now ends within half a step of t_end at the new
-- dt; a dt past the Courant limit is refused where it is set.
local sim = lamina.sim{ dt = 1e-3 }
local el = lamina.elastic{ rho = 1000, E = 1000, nu = 0.3 }
sim:body{ material = el, region = lamina.disk{ center = {0.5, 0.5}, radius = 0.2 } }
sim:at(0.005, function(s) s.dt = 2e-3 end)
sim:run{ t_end = 0.01 }
assert(math.abs(sim.t - 0.01) <= 0.5 * sim.dt + 1e-12, "ran to t = " .. sim.t)
local ok, err = pcall(function() sim.dt = 1e300 end)
assert(not ok and sim.dt == 2e-3, "dt = " .. sim.dt)
sim:at(0.012, function(s) s.dt = 1e300 end)
sim:run{ t_end = 0.02 }
