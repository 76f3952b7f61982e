-- expect: 2
-- stderr: sim:membrane: force = "springs" is not one of "point" \| "segment"
local sim = lamina.sim{domain = {0, 0, 2, 1}, cell = 0.05, dt = 1e-5}
local mat = lamina.membrane{rho = 1000, E = 1e7, nu = 0, thickness = 0.005, law = "uniaxial"}
sim:membrane{material = mat, force = "springs", spacing = 0.05 / 3,
             curve = lamina.segment{from = {0.2, 0.5}, to = {1.8, 0.5}}}
