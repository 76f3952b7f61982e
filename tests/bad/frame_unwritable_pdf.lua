-- expect: 2
-- stderr: frame_unwritable_pdf\.lua:8: sim:frame: cannot write '.*frame_unwritable_pdf\.lua/f\.pdf'
-- PDF (and SVG) frames are written atomically like PNGs: an unwritable
-- path is an error naming it, and no partial file is left.
local sim = lamina.sim{ dt = 1e-3 }
local m = lamina.elastic{ rho = 1, E = 1, nu = 0.3 }
sim:body{ material = m, region = lamina.disk{ center = {0.5, 0.5}, radius = 0.2 } }
sim:frame{ file = SCRIPT .. "/f.pdf" }
