-- expect: 2
-- stderr: link_contact\.lua:10: sim:contact: body 2 has a link: links and contact do not mix yet
-- A contact pair on a linked body is refused (the pair's own fields would
-- not see the link's force), naming the body.
local sim = lamina.sim{ basis = "gimp", dt = 1e-4 }
local m = lamina.elastic{ rho = 1000, E = 1e6 }
local a = sim:body{ material = m, region = lamina.disk{ center = {0.3, 0.5}, radius = 0.1 } }
local b = sim:body{ material = m, region = lamina.disk{ center = {0.7, 0.5}, radius = 0.1 } }
sim:link{ a = {b, 1}, b = {b, 2}, stiffness = 1e3 }
sim:contact{ a, b, law = "release" }
