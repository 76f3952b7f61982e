-- expect: 2
-- stderr: frame_vector_osmesa\.lua:8: sim:frame: (cannot write 'out/frame_vector_osmesa\.svg': SVG output is drawn by cairo, not by the osmesa backend|backend = "osmesa": this lamina was built without OSMesa)
-- SVG and PDF are cairo's: asking OSMesa for one is refused (a run-wide
-- --backend osmesa leaves vector frames to cairo instead).
local sim = lamina.sim{ dt = 1e-3 }
local m = lamina.elastic{ rho = 1, E = 1, nu = 0.3 }
sim:body{ material = m, region = lamina.disk{ center = {0.5, 0.5}, radius = 0.2 } }
sim:frame{ file = "out/frame_vector_osmesa.svg", backend = "osmesa" }
