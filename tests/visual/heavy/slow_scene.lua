-- title: A figure marked heavy
-- source: none: the gallery's own test (docs/gallery.md "Heavy figures")
-- look: one disc
-- heavy: stands for the finest meshes, which take minutes
local out = lamina.param("out", "out/slow_scene")
local sim = lamina.sim{ basis = "linear", dt = 1e-3 }
sim:body{ material = lamina.elastic{ rho = 1000, E = 1e6 },
          region = lamina.disk{ center = {0.5, 0.5}, radius = 0.2 } }
sim:frame{ file = out .. "/disc.png", width = 64, height = 64 }
