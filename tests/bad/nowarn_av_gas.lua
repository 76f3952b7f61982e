-- expect: 0
-- stderr-not: has av
-- What is not warned of as the artificial viscosity (sod30; l_option_warn.c):
-- a gas without av, and a gas whose av is switched off live before the
-- run ("Live: mu, av", docs/api.md).
local sim = lamina.sim{ domain = {0, 0, 1, 0.1}, cell = 0.1, dt = 0.01 }
sim:body{ material = lamina.gas{ rho = 1, p = 1 }, region = lamina.rect{ x0 = 0, y0 = 0, x1 = 0.5, y1 = 0.1 } }
local m = lamina.gas{ rho = 0.125, p = 0.1, av = true }
sim:body{ material = m, region = lamina.rect{ x0 = 0.5, y0 = 0, x1 = 1, y1 = 0.1 } }
m.av = false
sim:run{ t_end = 0.05 }
