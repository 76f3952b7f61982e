-- expect: 2
-- stderr: sim3_plane\.lua:6: sim:body: 'material' has 'plane' set: a 3D solid has no plane assumption
-- lamina.elastic{plane = ...} given to a 3D body (issue 34 item 1).
local sim = lamina.sim{ dim = 3, domain = {0, 0, 0, 1, 1, 1}, cell = 0.1, dt = 1e-3 }
local m = lamina.elastic{ rho = 1000, E = 1e6, nu = 0.3, plane = "stress" }
sim:body{ material = m, region = lamina.ball{ center = {0.5, 0.5, 0.5}, radius = 0.2 } }
