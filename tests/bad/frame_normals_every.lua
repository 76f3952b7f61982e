-- expect: 2
-- stderr: frame_normals_every\.lua:7: sim:frame: 'normals' must be true, false or a whole number k >= 1
-- normals = k draws every k-th membrane point's normal; a fraction is refused.
local sim = lamina.sim{ dt = 1e-3 }
local m = lamina.elastic{ rho = 1, E = 1, nu = 0.3 }
sim:body{ material = m, region = lamina.disk{ center = {0.5, 0.5}, radius = 0.2 } }
sim:frame{ file = "out/frame_normals_every.png", normals = 2.5 }
