-- expect: 2
-- stderr: membrane_outside\.lua:7: sim:membrane: membrane 'rim' leaves the domain: point 8 at \(1\.017
-- A curve that leaves the domain is refused, naming the membrane and the
-- first point outside.
local sim = lamina.sim{ cell = 0.1, dt = 1e-5 }
local m = lamina.membrane{ rho = 1, E = 1e4, thickness = 0.01 }
sim:membrane{ material = m, name = "rim", spacing = 0.05,
              curve = lamina.arc{ center = {0.7, 0.5}, radius = 0.5, from = -90, to = 90 } }
