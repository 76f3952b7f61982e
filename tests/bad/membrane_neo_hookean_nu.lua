-- expect: 2
-- stderr: membrane_neo_hookean_nu\.lua:7: lamina\.membrane: law "neo_hookean" is incompressible \(nu = 0\.5\): leave nu out or give 0\.5 \(got 0\.3\)
-- The incompressible neo-Hookean membrane has no Poisson's ratio to give
-- (src/mpm/membrane_law_neo_hookean.c): nu = 0.5 or none is accepted, any
-- other value refused, naming the law and the value.
lamina.membrane{rho = 1000, E = 3e4, thickness = 0.01, law = "neo_hookean", nu = 0.5}
local m = lamina.membrane{rho = 1000, E = 3e4, nu = 0.3, thickness = 0.01, law = "neo_hookean"}
