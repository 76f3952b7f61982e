-- expect: 2
-- stderr: membrane_material\.lua:6: sim:membrane: 'material' must be lamina\.membrane
-- A solid material given to a membrane.
local sim = lamina.sim{ cell = 0.1, dt = 1e-5 }
local m = lamina.elastic{ rho = 1, E = 1e4 }
sim:membrane{ material = m, spacing = 0.05,
              curve = lamina.segment{ from = {0.2, 0.5}, to = {0.8, 0.5} } }
