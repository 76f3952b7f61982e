-- expect: 2
-- stderr: membrane_spacing\.lua:7: sim:membrane: membrane 'skin' spacing 0\.15 is larger than a cell \(0\.1\)
-- Neighbouring membrane points more than a cell apart break the membrane
-- ([M] §3): refused, naming the membrane and the value.
local sim = lamina.sim{ cell = 0.1, dt = 1e-5 }
local m = lamina.membrane{ rho = 1, E = 1e4, thickness = 0.01 }
sim:membrane{ material = m, name = "skin", spacing = 0.15,
              curve = lamina.segment{ from = {0.2, 0.5}, to = {0.8, 0.5} } }
