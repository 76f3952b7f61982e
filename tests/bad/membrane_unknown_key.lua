-- expect: 2
-- stderr: membrane_unknown_key\.lua:6: sim:membrane: unknown key 'endmass'
local sim = lamina.sim{ cell = 0.1, dt = 1e-5 }
local m = lamina.membrane{ rho = 1, E = 1e4, thickness = 0.01 }
local c = lamina.segment{ from = {0.2, 0.5}, to = {0.8, 0.5} }
sim:membrane{ material = m, spacing = 0.05, curve = c, endmass = 3 }
