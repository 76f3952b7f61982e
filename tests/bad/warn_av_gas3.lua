-- expect: 0
-- stderr: warning: a 3D gas \(material 1\) has av \(the artificial viscosity, \[F\] eq 24\): .*-0\.9 %.*case sod
-- stderr-once: has av
-- A 3D gas with the artificial viscosity is warned of once, as a 2D one is
-- (bad.warn_av_gas; l_option_warn.c la_option_warn3): the 3D gas is the
-- same scheme ([F] eqs 21-25, sim3_gas.c), and scripts/examples/sod3d.lua's
-- left plateau sits low as the 2D page's. Two sims, one warning.
local dx = 0.1
for k = 1, 2 do
  local sim = lamina.sim{ dim = 3, domain = {0, 0, 0, dx, dx, 1}, cell = dx, dt = 1e-3,
                          boundary = { x0 = "symmetry", x1 = "symmetry", y0 = "symmetry",
                                       y1 = "symmetry", z0 = "fixed", z1 = "fixed" } }
  sim:body{ material = lamina.gas{ rho = 1, p = 1, av = true }, name = "hi",
            region = lamina.box{ x0 = 0, y0 = 0, z0 = 0, x1 = dx, y1 = dx, z1 = 0.5 } }
  sim:body{ material = lamina.gas{ rho = 0.125, p = 0.1, av = true }, name = "lo",
            region = lamina.box{ x0 = 0, y0 = 0, z0 = 0.5, x1 = dx, y1 = dx, z1 = 1 } }
  sim:run{ t_end = 0.01 }
  sim:step(2)
end
