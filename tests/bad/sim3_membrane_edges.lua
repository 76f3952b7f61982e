-- expect: 2
-- stderr: sim3_membrane_edges\.lua:7: sim:membrane: pin = "edges": a sphere is closed and has no edges
-- pin = "edges" names a parallelogram's rows; a sphere has none.
local sim = lamina.sim{ dim = 3, domain = {0, 0, 0, 1, 1, 1}, cell = 0.1, dt = 1e-3 }
local skin = lamina.membrane{ rho = 1000, E = 1e6, nu = 0.3, thickness = 1e-3, law = "plane_stress" }
local ball = lamina.sphere{ center = {0.5, 0.5, 0.5}, radius = 0.3 }
sim:membrane{ material = skin, surface = ball, spacing = 0.05, pin = "edges" }
