-- expect: 2
-- stderr: sim3_pin_ends\.lua:6: body:pin: points = "ends" is a membrane's; a 3D solid takes "all", a list of indices or a function\(x, y, z\)
-- A 2D pin option with no meaning for a 3D solid, refused by name.
local sim = lamina.sim{ dim = 3, domain = {0, 0, 0, 1, 1, 1}, cell = 0.1, dt = 1e-3 }
local b = sim:body{ material = lamina.elastic{ rho = 1000, E = 1e6 }, region = lamina.ball{ center = {0.5, 0.5, 0.5}, radius = 0.2 } }
b:pin{ points = "ends" }
