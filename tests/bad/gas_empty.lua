-- expect: 2
-- stderr: gas_empty\.lua:6: sim:body: the region holds no particles at ppc = 16
-- A gas region thinner than the particle pattern holds no particles.
local sim = lamina.sim{ cell = 0.1, dt = 1e-5 }
local air = lamina.gas{ rho = 1, e = 250 }
sim:body{ material = air, ppc = 16, region = lamina.rect{ x0 = 0.5, y0 = 0.5, x1 = 0.51, y1 = 0.51 } }
