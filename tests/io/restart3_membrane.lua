-- For restart3_membrane.sh: a 3D run checkpointed without membranes
-- (membrane=false), and the same script with a membrane (membrane=true)
-- given that checkpoint, which --restart must refuse.
local out = lamina.param("out", "out/restart3_membrane/a")
local sim = lamina.sim{ dim = 3, domain = {0, 0, 0, 1, 1, 1}, cell = 0.1, dt = 1e-3 }
sim:body{ material = lamina.elastic{ rho = 1000, E = 1e6 },
          region = lamina.box{ min = {0.3, 0.3, 0.3}, max = {0.6, 0.6, 0.6} } }
if lamina.param("membrane", false) then
  sim:membrane{ material = lamina.membrane{ rho = 1000, E = 1e6, nu = 0.3, thickness = 1e-3,
                                            law = "plane_stress" }, spacing = 0.05,
                surface = lamina.rect3{ origin = {0.2, 0.2, 0.8}, u = {0.6, 0, 0}, v = {0, 0.6, 0} } }
else
  sim:checkpoint{ file = out .. ".ckpt", at = 0.01 }
end
sim:run{ t_end = 0.02 }
