-- expect: 2
-- stderr: frame_unwritable\.lua:10: sim:frame: cannot write 'out/bad/frame_unwritable\.png/f\.png'.*not a directory
-- A frame path that cannot be written (here a folder that is a file) is a
-- clear error naming the path; no partial file is left (see test_png).
local sim = lamina.sim{ dt = 1e-3 }
local m = lamina.elastic{ rho = 1, E = 1, nu = 0.3 }
sim:body{ material = m, region = lamina.disk{ center = {0.5, 0.5}, radius = 0.2 } }
-- a folder that is a file (inside the output root: the working directory)
sim:frame{ file = "out/bad/frame_unwritable.png", width = 16, height = 16 }
sim:frame{ file = "out/bad/frame_unwritable.png/f.png" }
