-- title: An axisymmetric gas-filled sphere revolved about its axis
-- source: a test scene of lamina's own (issue 15 item 4): the sphere of
--   tests/physics/axisym_sphere.lua, drawn by assets/lua/revolve.lua
-- look: a sphere of meridians (black) and rings (grey), its far half only,
--   both poles on the dashed axis; inside it the gas particles of the cut
--   plane, a full disc (the section and its mirror) facing the viewer
-- checks: the picture against its baseline (the revolve module's geometry:
--   a ring's radius is the point's r, its height the point's z)
-- visual: t_end=0.002
-- thumb: sphere3d.png
local out = lamina.param("out", "out/revolve")
local t_end = lamina.param("t_end", 0.002)
local revolve = require("revolve")
local sim = lamina.sim{ domain = {0, -1, 1, 1}, cell = 0.1, dt = 0.5e-4, axisymmetric = true,
                        basis = "bspline2",
                        boundary = { left = "symmetry", bottom = "fixed", right = "fixed",
                                     top = "fixed" } }
local air = lamina.gas{ rho = 1, p = 1000, gamma = 1.4, mu = 0.2 }
local skin = lamina.membrane{ rho = 0.5, E = 1e6, nu = 0.3, thickness = 0.1,
                              law = "plane_stress" }
local gas = sim:body{ material = air, ppc = 4, name = "gas", fill = "clipped",
                      region = lamina.disk{ center = {0, 0}, radius = 0.5 } }
local mem = sim:membrane{ material = skin, count = 61, name = "membrane", force = "segment",
                          orient = {0, 0},
                          curve = lamina.arc{ center = {0, 0}, radius = 0.5, from = -90, to = 90 } }
sim:run{ t_end = t_end }
revolve.frame(sim, { file = out .. "/sphere3d.png", bodies = {gas, mem}, width = 400,
                     height = 360, title = "a sphere revolved" })
lamina.report{ state_hash = sim:hash() }
