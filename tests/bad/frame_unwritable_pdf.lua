-- expect: 2
-- stderr: frame_unwritable_pdf\.lua:10: sim:frame: cannot write 'out/bad/frame_unwritable_pdf\.png/f\.pdf'.*not a directory
-- PDF (and SVG) frames are written atomically like PNGs: an unwritable
-- path is an error naming it, and no partial file is left.
local sim = lamina.sim{ dt = 1e-3 }
local m = lamina.elastic{ rho = 1, E = 1, nu = 0.3 }
sim:body{ material = m, region = lamina.disk{ center = {0.5, 0.5}, radius = 0.2 } }
-- a folder that is a file (inside the output root: the working directory)
sim:frame{ file = "out/bad/frame_unwritable_pdf.png", width = 16, height = 16 }
sim:frame{ file = "out/bad/frame_unwritable_pdf.png/f.pdf" }
