-- expect: 2
-- stderr: axisym_gas_split\.lua:7: sim:body: axisymmetric: gas splitting \(split = 4\.0\) is plane only
-- Splitting and the cell densities count area, not r dA: refused in the
-- axisymmetric form rather than run wrong.
local sim = lamina.sim{ domain = {0, 0, 1, 1}, dt = 1e-4, axisymmetric = true,
                        boundary = { left = "symmetry" } }
sim:body{ material = lamina.gas{ rho = 1, p = 1, split = 4 }, region = lamina.disk{ center = {0, 0.5}, radius = 0.2 } }
