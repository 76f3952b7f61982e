-- expect: 2
-- stderr: axisym_membrane_axis\.lua:9: sim:membrane: axisymmetric: membrane 'skin' crosses the axis r = 0 at point 1 \(-0\.1, 0\.5\); only an end
-- A membrane point is a ring about the axis: a curve reaching r < 0 (here
-- a circle drawn across the axis) is refused by name (issue 15 item 6).
local sim = lamina.sim{ domain = {0, 0, 1, 1}, cell = 0.1, dt = 1e-4, axisymmetric = true,
                        boundary = { left = "symmetry" } }
local skin = lamina.membrane{ rho = 1, E = 1e5, thickness = 0.01 }
local curve = lamina.segment{ from = {-0.1, 0.5}, to = {0.5, 0.5} }
sim:membrane{ material = skin, spacing = 0.05, name = "skin",
  curve = curve }
