-- expect: 2
-- stderr: link_point\.lua:8: sim:link: b\[2\] must be a point of the body, a whole number from 1 to [0-9]+
-- A point index outside the body names the range.
local sim = lamina.sim{ dt = 1e-4 }
local m = lamina.elastic{ rho = 1000, E = 1e6 }
local a = sim:body{ material = m, region = lamina.disk{ center = {0.3, 0.5}, radius = 0.1 } }
local b = sim:body{ material = m, region = lamina.disk{ center = {0.7, 0.5}, radius = 0.1 } }
sim:link{ a = {a, 1}, b = {b, 1000}, stiffness = 1e3 }
