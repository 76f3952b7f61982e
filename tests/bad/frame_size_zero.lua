-- expect: 2
-- stderr: frame_size_zero\.lua:8: sim:frame: width and height must be whole numbers in \[16, 16384\]
-- A frame of zero width is refused with the allowed range (docs/api.md,
-- docs/rendering.md: 16 to 16384 pixels a side, for every backend).
local sim = lamina.sim{ dt = 1e-3 }
local m = lamina.elastic{ rho = 1, E = 1, nu = 0.3 }
sim:body{ material = m, region = lamina.disk{ center = {0.5, 0.5}, radius = 0.2 } }
sim:frame{ file = "out/frame_size_zero.png", width = 0 }
