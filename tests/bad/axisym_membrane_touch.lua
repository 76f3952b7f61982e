-- expect: 2
-- stderr: axisym_membrane_touch\.lua:9: sim:membrane: axisymmetric: membrane 1 crosses the axis r = 0 at point 19 \(0\.0, 0\.5\); only an end of an open membrane may lie on it
-- Only an end of a membrane may lie on the axis (a pole); a point between
-- would be a ring of no size in the middle of the surface (here a closed
-- circle touching the axis).
local sim = lamina.sim{ domain = {0, 0, 1, 1}, cell = 0.1, dt = 1e-4, axisymmetric = true,
                        boundary = { left = "symmetry" } }
local skin = lamina.membrane{ rho = 1, E = 1e5, thickness = 0.01 }
sim:membrane{ material = skin, count = 36,
              curve = lamina.arc{ center = {0.1, 0.5}, radius = 0.1 } }
