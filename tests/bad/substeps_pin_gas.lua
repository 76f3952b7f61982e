-- expect: 1
-- stderr: substeps \(multi-rate stepping\) does not work with a pin on a body that is not a membrane \(the simulation's pin 1, on body 2\); leave substeps out
-- Multi-rate stepping solves point pins on membranes in every sub-step
-- (src/mpm/subcycle_terms.c); a pinned gas or solid particle's velocity is
-- set only at the step's end while its nodes would be held at every
-- sub-step: not derived, refused by name.
local sim = lamina.sim{ dt = 4e-4, substeps = 4, cell = 1 / 32 }
local mat = lamina.membrane{ rho = 1, E = 1e4, nu = 0, thickness = 0.01, law = "uniaxial" }
sim:membrane{ material = mat, initial_strain = 0.05, spacing = 1 / 64,
              curve = lamina.segment{ from = {0.2, 0.5}, to = {0.8, 0.5} } }
local block = sim:body{ material = lamina.elastic{ rho = 1000, E = 1e5, nu = 0.3 }, ppc = 4,
                        region = lamina.rect{ x0 = 0.3, y0 = 0.2, x1 = 0.5, y1 = 0.3 } }
block:pin{ points = {1} }
sim:run{ t_end = 1e-3 }
