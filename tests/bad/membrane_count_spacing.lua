-- expect: 2
-- stderr: membrane_count_spacing\.lua:6: sim:membrane: membrane 1 spacing 0\.3 is larger than a cell \(0\.1\)
-- A count too small for the curve's length gives the same error.
local sim = lamina.sim{ cell = 0.1, dt = 1e-5 }
local m = lamina.membrane{ rho = 1, E = 1e4, thickness = 0.01 }
sim:membrane{ material = m, count = 3, curve = lamina.segment{ from = {0.2, 0.5}, to = {0.8, 0.5} } }
