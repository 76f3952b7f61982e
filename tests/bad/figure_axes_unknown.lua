-- expect: 2
-- stderr: figure_axes_unknown\.lua:5: figure:panel
-- axes = "ends" | "outside" places a 3D box's axis names; others are named.
local fig = lamina.figure{ width = 200, height = 200, backend = "cairo" }
fig:panel{ index = 1, box = {0, 0, 0, 1, 1, 1}, axes = "inside" }
