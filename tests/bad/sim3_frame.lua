-- expect: 2
-- stderr: sim:frame: unknown key 'colr' \(known keys: file,
-- sim:frame{} of a 3D sim takes the 3D frame's keys (docs/api.md "3D frames");
-- a misspelt one is refused by name, nothing written.
local sim = lamina.sim{ dim = 3, domain = {0, 0, 0, 1, 1, 1}, cell = 0.1, dt = 1e-3 }
sim:frame{ file = "out/bad/sim3_frame.png", colr = "speed" }
