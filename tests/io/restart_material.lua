-- A material changed live, then a restart (issue 33 item 1; driven by
-- tests/io/restart_material.sh): the engine owns copies of its materials,
-- and a checkpoint restores them; the script's material must read the
-- restored value too, and so must every sim it was given to. rubber.E is
-- doubled by a callback at t = 0.03; a run to 0.06 checkpoints at 0.05;
-- restarted from there, the callback does not run again, yet rubber.E is
-- 2000 and the state ends as the uninterrupted run's.
local t_end = lamina.param("t_end", 0.1)
local out = lamina.param("out", "out/restart_material/a")
local rubber = lamina.elastic{ rho = 1000, E = 1000, nu = 0.3 }
local sim = lamina.sim{ domain = {0, 0, 1, 1}, cell = 0.05, dt = 1e-3 }
sim:body{ material = rubber, velocity = {0.2, 0.1},
          region = lamina.disk{ center = {0.4, 0.4}, radius = 0.15 } }
sim:at(0.03, function() rubber.E = 2000 end)
sim:checkpoint{ file = lamina.param("ck", out .. ".ckpt"), every = 0.05 }
sim:run{ t_end = t_end }
print(string.format("RESULT E %g hash %s", rubber.E, sim:hash()))
