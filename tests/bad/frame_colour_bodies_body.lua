-- expect: 2
-- stderr: frame_colour_bodies_body\.lua:9: sim:frame: 'colour_bodies' needs colour = a field
-- colour_bodies names the bodies coloured by the field: without a field it means nothing.
local sim = lamina.sim{ dt = 1e-3 }
local m = lamina.elastic{ rho = 1, E = 1, nu = 0.3 }
local a = sim:body{ material = m, region = lamina.disk{ center = {0.3, 0.5}, radius = 0.15 } }
sim:body{ material = m, region = lamina.disk{ center = {0.7, 0.5}, radius = 0.15 } }
-- colour defaults to "body"
sim:frame{ file = "out/frame_colour_bodies_body.png", colour_bodies = { a } }
