-- expect: 1
-- stderr: substeps \(multi-rate stepping\) does not work with pins \(body:pin\); leave substeps out
-- Multi-rate stepping holds the gas's nodal forces through the membrane's
-- sub-steps; pins (like contact, links, heavy end points, damping, the
-- corrected mass, the cell stress and the axisymmetric form) act on the
-- nodes inside the step and are refused by name, not run wrong.
local sim = lamina.sim{ dt = 4e-4, substeps = 4, cell = 1 / 32 }
local mat = lamina.membrane{ rho = 1, E = 1e4, nu = 0, thickness = 0.01, law = "uniaxial" }
local s = sim:membrane{ material = mat, initial_strain = 0.05, spacing = 1 / 64,
                        curve = lamina.segment{ from = {0.2, 0.5}, to = {0.8, 0.5} } }
s:pin{ points = {1} }
sim:run{ t_end = 1e-3 }
