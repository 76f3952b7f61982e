-- title: negative control of check_membrane_frames.py: a wire drawn bare
-- source: lamina's own (issue 32 item 1)
-- look: a membrane frame with phi = false and normals = false, which the
--   check must report (tests/visual/CMakeLists.txt, visual.membrane_frames_negative)
local out = lamina.param("out", "out/bare_wire")
local sim = lamina.sim{ basis = "linear", domain = {0, 0, 2, 2}, cell = 0.2, dt = 1e-3 }
local wire = lamina.membrane{ rho = 0.5, E = 1e4, thickness = 0.0125 }
sim:membrane{ material = wire, spacing = 0.05,
              curve = lamina.segment{ from = {1, 0.2}, to = {1, 1.8} } }
sim:frame{ file = out .. "/shown.png", width = 200, height = 200 }
sim:frame{ file = out .. "/bare.png", width = 200, height = 200, phi = false, normals = false }
