-- expect: 1
-- stderr: substeps \(multi-rate stepping\) does not work with a pin whose points share grid nodes \(it holds its nodes: pin.c\) \(the simulation's pin 1, on membrane 1\); leave substeps out
-- Multi-rate stepping holds the gas's nodal forces through the membrane's
-- sub-steps; a point pin on a membrane is solved in every sub-step
-- (src/mpm/subcycle_terms.c), but a pin whose points share nodes holds
-- its nodes (pin.c), which the sub-steps do not do: refused by name, not
-- run wrong.
local sim = lamina.sim{ dt = 4e-4, substeps = 4, cell = 1 / 32 }
local mat = lamina.membrane{ rho = 1, E = 1e4, nu = 0, thickness = 0.01, law = "uniaxial" }
local s = sim:membrane{ material = mat, initial_strain = 0.05, spacing = 1 / 64,
                        curve = lamina.segment{ from = {0.2, 0.5}, to = {0.8, 0.5} } }
s:pin{ points = {1, 2} }
sim:run{ t_end = 1e-3 }
