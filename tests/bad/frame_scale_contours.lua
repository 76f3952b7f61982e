-- expect: 2
-- stderr: frame_scale_contours\.lua:9: sim:frame: contours = "pressure" is a field of the grid, drawn where the points are: it cannot be drawn with 'scale' = 10
-- Layers that are fields of the grid cannot follow points drawn at
-- X0 + k (x - X0): asked for with scale = k, they are refused by name.
local sim = lamina.sim{ dt = 1e-3 }
local g = lamina.gas{ rho = 1, p = 10 }
sim:body{ material = g, ppc = 4, region = lamina.disk{ center = {0.5, 0.5}, radius = 0.2 } }
sim:step()
sim:frame{ file = "out/frame_scale_contours.png", scale = 10, contours = "pressure" }
