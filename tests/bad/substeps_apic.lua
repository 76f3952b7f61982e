-- expect: 1
-- stderr: substeps \(multi-rate stepping\) does not work with transfer = "apic"; leave substeps out
-- Multi-rate stepping re-maps the slow group with FLIP's transfers (subcycle.c);
-- the affine transfer's matrices would not follow it, so the pair is refused
-- by name, not run wrong.
local sim = lamina.sim{ dt = 4e-4, substeps = 4, cell = 1 / 32, transfer = "apic" }
local mat = lamina.membrane{ rho = 1, E = 1e4, nu = 0, thickness = 0.01, law = "uniaxial" }
sim:membrane{ material = mat, initial_strain = 0.05, spacing = 1 / 64,
              curve = lamina.segment{ from = {0.2, 0.5}, to = {0.8, 0.5} } }
local air = lamina.gas{ rho = 1, gamma = 1.4, p = 1 }
sim:body{ material = air, region = lamina.rect{ x0 = 0.3, y0 = 0.2, x1 = 0.7, y1 = 0.4 } }
sim:run{ t_end = 1e-3 }
