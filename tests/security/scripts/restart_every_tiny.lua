-- Used by tests/security/restart_every_tiny.sh (issue 31 item 4).
local sim = lamina.sim{ dt = 1e-3, domain = {0, 0, 1, 1}, cell = 0.1 }
local el = lamina.elastic{ rho = 1000, E = 1000, nu = 0.3 }
sim:body{ material = el, region = lamina.disk{ center = {0.5, 0.5}, radius = 0.2 } }
local n = 0
sim:every(1e-300, function() n = n + 1 end)
sim:checkpoint{ file = "out/security/restart_every_tiny.ck", at = 0.005 }
sim:run{ t_end = 0.01 }
print("calls " .. n .. " steps " .. sim.nstep)
