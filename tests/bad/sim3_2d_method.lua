-- expect: 2
-- stderr: sim3_2d_method\.lua:5: sim:contact: not available for a 3D simulation \(dim = 3\) in this build \(issue 34
-- A 2D-only method on a 3D sim is refused naming it (not "attempt to call a nil value").
local sim = lamina.sim{ dim = 3, domain = {0, 0, 0, 1, 1, 1}, cell = 0.1, dt = 1e-3 }
sim:contact{}
