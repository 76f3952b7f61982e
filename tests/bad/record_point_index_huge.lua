-- expect: 2
-- stderr: record_point_index_huge\.lua:8: sim:record: points\.tip: index 1000000000000000000 is not a point of the body: a whole number from 1 to [0-9]+, or from -1 back to -[0-9]+
-- Issue 31 item 7: an index of 1e18 was reported as -1486618624 (cast to
-- int), and NaN as "bad argument #-1 to ?". Both are shown as given.
local sim = lamina.sim{ dt = 1e-3, domain = {0, 0, 1, 1}, cell = 0.1 }
local b = sim:body{ material = lamina.elastic{ rho = 1000, E = 1e5 }, region = lamina.disk{ center = {0.5, 0.5}, radius = 0.2 } }
assert(not tostring(select(2, pcall(sim.record, sim, { points = { tip = {b, 0/0} } }))):find("#-1", 1, true))
sim:record{ points = { tip = {b, 1000000000000000000} } }
