-- expect: 1
-- stderr: substeps \(multi-rate stepping\) does not work with fast_band and a gas with av \(its maxima are over the whole gas\); leave substeps out
-- The artificial viscosity ([F] eq 24) scales by maxima over the whole gas
-- of the step, which the fast gas points' sub-steps do not see
-- (src/mpm/subcycle_gasband.c): the pair is refused by name, not run wrong.
local sim = lamina.sim{ dt = 4e-4, substeps = 4, cell = 1 / 32, fast_band = 1 }
local mat = lamina.membrane{ rho = 1, E = 1e4, nu = 0, thickness = 0.01, law = "uniaxial" }
sim:membrane{ material = mat, initial_strain = 0.05, spacing = 1 / 64,
              curve = lamina.segment{ from = {0.2, 0.5}, to = {0.8, 0.5} } }
local air = lamina.gas{ rho = 1, gamma = 1.4, p = 1, av = true }
sim:body{ material = air, region = lamina.rect{ x0 = 0.3, y0 = 0.2, x1 = 0.7, y1 = 0.4 } }
sim:run{ t_end = 1e-3 }
