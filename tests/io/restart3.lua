-- Checkpoint and restart of a 3D run (issue 34 item 1), for restart3.sh:
-- a ball thrown onto the floor, a box and a gas, recorded, checkpointed every 0.05;
-- prints "RESULT t ... hash H" at the end. --set make2d=true instead makes
-- a 2D run's checkpoint (the refusal of the other dimension's file).
local out = lamina.param("out", "out/restart3/a")
local t_end = lamina.param("t_end", 0.2)
local radius = lamina.param("radius", 0.1)
if lamina.param("make2d", false) then
  local s = lamina.sim{ domain = {0, 0, 1, 1}, cell = 0.1, dt = 1e-3 }
  s:body{ material = lamina.elastic{ rho = 1000, E = 1e5 },
          region = lamina.disk{ center = {0.5, 0.5}, radius = 0.2 } }
  s:checkpoint{ file = out .. ".ckpt", at = 0.01 }
  s:run{ t_end = 0.01 }
  return
end
local sim = lamina.sim{ dim = 3, domain = {0, 0, 0, 0.5, 0.5, 0.5}, cell = 0.05, dt = 1e-3,
                        gravity = {0, 0, -9.81}, boundary = { z1 = "free" } }
local rock = lamina.elastic{ rho = 1000, E = 1e5, nu = 0.3 }
local ball = sim:body{ material = rock, velocity = {0.3, 0.1, -1},
                       region = lamina.ball{ center = {0.2, 0.25, 0.25}, radius = radius } }
sim:body{ material = lamina.elastic{ rho = 500, E = 5e4, nu = 0.2 }, ppc = {2, 2, 1},
          region = lamina.box{ min = {0.3, 0.1, 0}, max = {0.45, 0.4, 0.1} } }
-- a gas (issue 34 item 1): its e and constants are in the checkpoint, the
-- CSV's internal energy (sum m e) shows them restored
sim:body{ material = lamina.gas{ rho = 1000, p = 1, av = true, mu = 0.01 }, ppc = 8,
          region = lamina.box{ min = {0, 0, 0}, max = {0.1, 0.5, 0.2} } }
sim:record{ file = out .. ".csv", every = 0.01, energy = true,
            values = { zc = function() local _, _, z = ball:com() return z end } }
sim:checkpoint{ file = out .. ".ckpt", every = 0.05 }
sim:run{ t_end = t_end }
print(string.format("RESULT t %.6f step %d hash %s", sim.t, sim.nstep, sim:hash()))
