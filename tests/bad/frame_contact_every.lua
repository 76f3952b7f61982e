-- expect: 2
-- stderr: frame_contact_every\.lua:9: sim:frame: contact's 'every' must be a whole number k >= 1
-- contact = {every = k} keeps a node of each k x k block; a fraction is refused.
local sim = lamina.sim{ basis = "gimp", dt = 1e-3 }
local m = lamina.elastic{ rho = 1, E = 1, nu = 0.3 }
local a = sim:body{ material = m, region = lamina.disk{ center = {0.3, 0.5}, radius = 0.15 } }
local b = sim:body{ material = m, region = lamina.disk{ center = {0.7, 0.5}, radius = 0.15 } }
sim:contact{ a, b }
sim:frame{ file = "out/frame_contact_every.png", contact = { every = 1.5 } }
