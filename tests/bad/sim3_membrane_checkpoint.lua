-- expect: 2
-- stderr: sim3_membrane_checkpoint\.lua:9: sim:checkpoint: a 3D simulation with membranes cannot be checkpointed
-- The 3D state file holds no membrane points: a checkpoint that would
-- restart without the membranes is refused by name (nothing written).
local sim = lamina.sim{ dim = 3, domain = {0, 0, 0, 1, 1, 1}, cell = 0.1, dt = 1e-3 }
local skin = lamina.membrane{ rho = 1000, E = 1e6, nu = 0.3, thickness = 1e-3, law = "plane_stress" }
sim:membrane{ material = skin, spacing = 0.05,
              surface = lamina.rect3{ origin = {0.2, 0.2, 0.5}, u = {0.6, 0, 0}, v = {0, 0.6, 0} } }
sim:checkpoint{ file = "m.ckpt", at = 0.01 }
