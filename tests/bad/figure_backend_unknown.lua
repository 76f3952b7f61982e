-- expect: 2
-- stderr: figure_backend_unknown\.lua:5: lamina\.figure: unknown backend 'vulkan' \(known: cairo, osmesa, egl, gl\)
-- What draws a figure's 3D views is one of the backends, and an unknown one
-- is named with the known ones.
local fig = lamina.figure{ width = 64, height = 64, backend = "vulkan" }
