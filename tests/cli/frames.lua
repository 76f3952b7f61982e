-- Four small frames (t = 0, 0.05, 0.1, 0.15) of two elastic disks, and a checkpoint at t = 0.1:
-- the input of tests/cli/animate.sh and restart_says.sh (issue 35 item 5).
--   out    the folder of the frames and the checkpoint
--   t_end  how long it runs
local out = lamina.param("out", "out/frames")
local t_end = lamina.param("t_end", 0.15)
local sim = lamina.sim{ basis = "linear", domain = {0, 0, 1, 1}, cell = 0.1, dt = 1e-3 }
local rubber = lamina.elastic{ rho = 1000, E = 1000, nu = 0.3 }
sim:body{ material = rubber, ppc = 4, velocity = { 0.1,  0.1},
          region = lamina.disk{ center = {0.3, 0.3}, radius = 0.15 } }
sim:body{ material = rubber, ppc = 4, velocity = {-0.1, -0.1},
          region = lamina.disk{ center = {0.7, 0.7}, radius = 0.15 } }
sim:checkpoint{ file = out .. "/run.ckpt", at = 0.1 }
local k = 0
sim:every(0.05, function(s)
  k = k + 1
  s:frame{ file = string.format("%s/frames/frame_%04d.png", out, k), width = 48, height = 48 }
end)
sim:run{ t_end = t_end }
print(string.format("RESULT t %.6f step %d hash %s", sim.t, sim.nstep, sim:hash()))
