-- expect: 2
-- stderr: pressure_not_membrane\.lua:7: gas:pressure\(membrane\): needs a membrane of the same sim
local sim = lamina.sim{ dt = 1e-4 }
local air = lamina.gas{ rho = 1, p = 1, gamma = 1.4 }
local a = sim:body{ material = air, region = lamina.disk{ center = {0.5, 0.5}, radius = 0.2 } }
local b = sim:body{ material = air, region = lamina.disk{ center = {0.2, 0.2}, radius = 0.1 } }
print(a:pressure(b))
