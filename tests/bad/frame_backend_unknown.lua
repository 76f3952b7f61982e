-- expect: 2
-- stderr: frame_backend_unknown\.lua:7: sim:frame: unknown backend 'vulkan' \(known: cairo, osmesa, egl, gl\)
-- An unknown renderer is named with the known ones.
local sim = lamina.sim{ dt = 1e-3 }
local m = lamina.elastic{ rho = 1, E = 1, nu = 0.3 }
sim:body{ material = m, region = lamina.disk{ center = {0.5, 0.5}, radius = 0.2 } }
sim:frame{ file = "out/frame_backend_unknown.png", backend = "vulkan" }
