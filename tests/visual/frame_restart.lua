-- frame_restart.lua - sim:frame{scale = k} after `lamina run --restart`
-- (tests/visual/frame_check.py, issue 35 item 4): the reference positions
-- are the script's own build, captured before the checkpoint replaces the
-- state (src/lua/l_ref.c), so the frame at the end of a restarted run is
-- the frame at the end of the run the checkpoint came from. The string of
-- frame_scenes.lua, ringing at 0.2 % of its length; a checkpoint half way.
local out = lamina.param("out", "out/frame_restart")
local E, t, rho, h = 1e4, 0.01, 1, 1 / 32
local skin = lamina.membrane{ rho = rho, E = E, nu = 0, thickness = t, law = "uniaxial" }
local sim = lamina.sim{ dt = 0.4 * h / math.sqrt(E / rho), cell = h, domain = {0, 0, 1, 1},
                        boundary = { left = "fixed", right = "fixed", top = "free", bottom = "free" } }
local y0 = 0.5 + 0.3 * h
sim:membrane{ material = skin, initial_strain = 0.05, spacing = 0.5 * h,
  curve = lamina.segment{ from = {0, y0}, to = {1, y0} },
  velocity = function(u) return 0, 0.29 * math.sin(math.pi * u) end }
sim:checkpoint{ file = out .. "/half.ckpt", at = 0.01 }
sim:run{ t_end = 0.02 }
sim:frame{ file = out .. "/end.png", width = 320, height = 200, window = {-0.05, 0.3, 1.05, 0.7},
           grid = false, normals = false, scale = 100 }
