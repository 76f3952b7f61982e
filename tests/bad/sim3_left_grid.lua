-- expect: 1
-- stderr: sim3_left_grid\.lua:8: simulation failed: t = 0\.005 \(step 5\): particle 4 left the grid at x = 1\.025 \(the domain is 0 to 1\); likely cause: the body reached the domain's edge
-- A 3D run that fails stops naming the time, the step, the particle and the
-- likely cause (the run guard: exit status 1, the simulation's failure).
local sim = lamina.sim{ dim = 3, domain = {0, 0, 0, 1, 1, 1}, cell = 0.1, dt = 1e-3, boundary = "free" }
sim:body{ material = lamina.elastic{ rho = 1000, E = 1e6, nu = 0.3 }, velocity = {100, 0, 0},
          region = lamina.box{ min = {0.3, 0.3, 0.3}, max = {0.6, 0.6, 0.6} } }
sim:run{ t_end = 1 }
