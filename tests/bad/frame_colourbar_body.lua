-- expect: 2
-- stderr: frame_colourbar_body\.lua:7: sim:frame: 'colourbar' needs colour = a field
-- Colours by body have no scale to show.
local sim = lamina.sim{ dt = 1e-3 }
local m = lamina.elastic{ rho = 1, E = 1, nu = 0.3 }
sim:body{ material = m, region = lamina.disk{ center = {0.5, 0.5}, radius = 0.2 } }
sim:frame{ file = "out/frame_colourbar_body.png", colourbar = true }
