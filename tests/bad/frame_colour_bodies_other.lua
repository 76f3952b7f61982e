-- expect: 2
-- stderr: frame_colour_bodies_other\.lua:9: sim:frame: colour_bodies\[1\] is a body of a simulation this panel does not show
-- A body of a simulation the panel does not show is refused, not ignored.
local m = lamina.elastic{ rho = 1, E = 1, nu = 0.3 }
local sim = lamina.sim{ dt = 1e-3 }
sim:body{ material = m, region = lamina.disk{ center = {0.3, 0.5}, radius = 0.15 } }
local other = lamina.sim{ dt = 1e-3 }
local b = other:body{ material = m, region = lamina.disk{ center = {0.7, 0.5}, radius = 0.15 } }
sim:frame{ file = "out/frame_colour_bodies_other.png", colour = "speed",
           colour_bodies = { b } }
