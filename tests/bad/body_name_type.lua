-- expect: 2
-- stderr: body_name_type\.lua:7: sim:body: .name. must be a string \(got table\)
-- Issue 31 item 7: a body's or membrane's name took any type (a table or
-- a function showed as its address). Text, or nothing.
local sim = lamina.sim{ dt = 1e-3, domain = {0, 0, 1, 1}, cell = 0.1 }
assert(not pcall(sim.membrane, sim, { material = lamina.membrane{ rho = 1000, E = 1e5, thickness = 0.01 }, curve = lamina.arc{ center = {0.5, 0.5}, radius = 0.2 }, spacing = 0.05, name = true }))
sim:body{ material = lamina.elastic{ rho = 1000, E = 1e5 }, region = lamina.disk{ center = {0.5, 0.5}, radius = 0.2 }, name = {} }
