-- expect: 2
-- stderr: frame_unwritable_osmesa\.lua:10: sim:frame: (cannot write 'out/bad/frame_unwritable_osmesa\.png/f\.png'.*not a directory|backend = "osmesa": this lamina was built without OSMesa)
-- The OSMesa backend writes through the same PNG writer: an unwritable path
-- is the same clear error naming it (and a build without OSMesa says so).
local sim = lamina.sim{ dt = 1e-3 }
local m = lamina.elastic{ rho = 1, E = 1, nu = 0.3 }
sim:body{ material = m, region = lamina.disk{ center = {0.5, 0.5}, radius = 0.2 } }
-- a folder that is a file (inside the output root: the working directory)
sim:frame{ file = "out/bad/frame_unwritable_osmesa.png", width = 16, height = 16 }
sim:frame{ file = "out/bad/frame_unwritable_osmesa.png/f.png", backend = "osmesa", width = 64, height = 64 }
