-- expect: 2
-- stderr: sim:frame: 3D frames: not yet in this build \(issue 34 item 4
-- sim:frame{} of a 3D sim: refused clearly until the 3D renderer is wired.
local sim = lamina.sim{ dim = 3, domain = {0, 0, 0, 1, 1, 1}, cell = 0.1, dt = 1e-3 }
sim:frame{ file = "out/bad/sim3_frame.png" }
