-- expect: 2
-- stderr: membrane_spacing_tiny\.lua:11: sim:membrane: membrane 1 would have [0-9.]+ points, more than the limit of 10000000 per membrane
-- Issue 18, unclear messages: spacing = 1e-12 was reported as "spacing 0.8
-- is larger than a cell" (the count overflowed an int), and count = 1e12
-- overflowed too. Both name the limit on points per membrane now.
local sim = lamina.sim{ dt = 1e-4 }
local mem = lamina.membrane{ rho = 1000, E = 1e5, thickness = 0.01 }
local ok, err = pcall(sim.membrane, sim, { material = mem, count = 1e12,
                      curve = lamina.segment{ from = {0.2, 0.5}, to = {0.8, 0.5} } })
assert(not ok and err:find("1000000000000 points, more than the limit of 10000000"), tostring(err))
sim:membrane{ material = mem, spacing = 1e-12, curve = lamina.segment{ from = {0.2, 0.5}, to = {0.8, 0.5} } }
