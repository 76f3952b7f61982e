-- expect: 2
-- stderr: frame_discs_unknown\.lua:7: sim:frame: discs = "big" is not one of "smallest" \| "spacing"
-- Disc sizes are the smallest body's spacing or each body's own; others are named.
local sim = lamina.sim{ dt = 1e-3 }
local m = lamina.elastic{ rho = 1, E = 1, nu = 0.3 }
sim:body{ material = m, region = lamina.disk{ center = {0.5, 0.5}, radius = 0.2 } }
sim:frame{ file = "out/frame_discs_unknown.png", discs = "big" }
