-- expect: 2
-- stderr: frame_unwritable\.lua:8: sim:frame: .*frame_unwritable\.lua/f\.png
-- A frame path that cannot be written (here a folder that is a file) is a
-- clear error naming the path; no partial file is left (see test_png).
local sim = lamina.sim{ dt = 1e-3 }
local m = lamina.elastic{ rho = 1, E = 1, nu = 0.3 }
sim:body{ material = m, region = lamina.disk{ center = {0.5, 0.5}, radius = 0.2 } }
sim:frame{ file = SCRIPT .. "/f.png" }
