-- expect: 2
-- stderr: sim3_membrane_curve\.lua:6: sim:membrane: 'curve' is 2D only: a 3D membrane is a surface \(surface = lamina\.sphere
-- The 2D form's curve on a 3D sim is refused naming it and the 3D form.
local sim = lamina.sim{ dim = 3, domain = {0, 0, 0, 1, 1, 1}, cell = 0.1, dt = 1e-3 }
local skin = lamina.membrane{ rho = 1000, E = 1e6, nu = 0.3, thickness = 1e-3, law = "plane_stress" }
sim:membrane{ material = skin, curve = lamina.segment{ from = {0.2, 0.5}, to = {0.8, 0.5} } }
