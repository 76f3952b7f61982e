-- expect: 2
-- stderr: empty_region\.lua:6: sim:body: the region holds no particles
local sim = lamina.sim{ dt = 1e-3 }
local m = lamina.elastic{ rho = 1, E = 1, nu = 0.3 }
-- a disk outside the domain
sim:body{ material = m, region = lamina.disk{ center = {5, 5}, radius = 0.2 } }
