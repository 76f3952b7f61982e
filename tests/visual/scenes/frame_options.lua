-- title: sim:frame's legibility options on a small ball and net
-- source: lamina's own (issue 16 item 3; docs/api.md, sim:frame)
-- look: left, a close-up of the contact: the normals of one node in each
--   2 x 2 block, twice as long, on a white outline (contact = {every = 2,
--   scale = 2}); right, the net drawn as a band coloured by its speed while
--   the ball keeps its body colour (colour_bodies = {net}, band = 5), the
--   colour bar the net's range
-- checks: the state hash, so that a failing comparison says whether the
--   simulation or only the drawing changed
-- visual: t_end=0.7
local out = lamina.param("out", "out/frame_options")
local t_end = lamina.param("t_end", 0.7)

local sim = lamina.sim{ basis = "linear", domain = {0, 0, 4, 4}, cell = 0.2, dt = 1e-3 }
local ballm = lamina.elastic{ rho = 1, E = 1e4, nu = 0.3, plane = "stress" }
local netm = lamina.membrane{ rho = 0.5, E = 1e4, thickness = 0.0125 }
local net = sim:membrane{ material = netm, spacing = 0.2 / 3, force = "segment", name = "net",
                          curve = lamina.segment{ from = {2.5, 0}, to = {2.5, 4} } }
local ball = sim:body{ material = ballm, ppc = 4, velocity = {1, 0}, name = "ball",
                       region = lamina.disk{ center = {1.5, 2}, radius = 0.6 } }
sim:contact{ ball, net }
sim:run{ t_end = t_end }
sim:frame{ file = out .. "/options.png", width = 640, height = 340,
           panels = { { title = "contact = {every = 2, scale = 2}", window = {1.4, 1, 3.4, 3},
                        contact = { every = 2, scale = 2 } },
                      { title = "colour_bodies = {net}, band = 5", colour = "speed",
                        colour_bodies = { net }, band = 5, grid = false } } }
lamina.report{ state_hash = sim:hash(), steps = sim.nstep }
