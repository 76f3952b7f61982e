-- expect: 2
-- stderr: frame_layout_small\.lua:7: sim:frame: 'layout' \{1, 1\} has fewer cells than the 2 panels
-- A layout must hold every panel.
local sim = lamina.sim{ dt = 1e-3 }
local m = lamina.elastic{ rho = 1, E = 1, nu = 0.3 }
sim:body{ material = m, region = lamina.disk{ center = {0.5, 0.5}, radius = 0.2 } }
sim:frame{ file = "out/frame_layout_small.png", panels = { {}, {} }, layout = {1, 1} }
