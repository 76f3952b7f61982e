-- expect: 2
-- stderr: frame_band_width\.lua:7: sim:frame: 'band' must be a width in pixels in \(0, 64\]
-- band = w draws membranes as bands w pixels wide; zero is refused.
local sim = lamina.sim{ dt = 1e-3 }
local m = lamina.membrane{ rho = 1, E = 1, thickness = 0.01 }
sim:membrane{ material = m, spacing = 0.02, curve = lamina.segment{ from = {0.2, 0.5}, to = {0.8, 0.5} } }
sim:frame{ file = "out/frame_band_width.png", band = 0 }
