-- expect: 0
-- stderr-not: has av
-- A 3D gas without the artificial viscosity draws no av warning
-- (bad.warn_av_gas3 is the one that does).
local dx = 0.1
local sim = lamina.sim{ dim = 3, domain = {0, 0, 0, dx, dx, 1}, cell = dx, dt = 1e-3,
                        boundary = { x0 = "symmetry", x1 = "symmetry", y0 = "symmetry",
                                     y1 = "symmetry", z0 = "fixed", z1 = "fixed" } }
sim:body{ material = lamina.gas{ rho = 1, p = 1 }, name = "hi",
          region = lamina.box{ x0 = 0, y0 = 0, z0 = 0, x1 = dx, y1 = dx, z1 = 0.5 } }
sim:run{ t_end = 0.01 }
