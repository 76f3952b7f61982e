-- expect: 2
-- stderr: frame_size_huge\.lua:8: sim:frame: width and height must be whole numbers in \[16, 16384\] \(got 800\.0 x 100000\.0\)
-- A huge frame is refused before any memory is asked for: 16384 pixels a
-- side is the limit (cairo's and OSMesa's buffers alike).
local sim = lamina.sim{ dt = 1e-3 }
local m = lamina.elastic{ rho = 1, E = 1, nu = 0.3 }
sim:body{ material = m, region = lamina.disk{ center = {0.5, 0.5}, radius = 0.2 } }
sim:frame{ file = "out/frame_size_huge.png", height = 100000 }
