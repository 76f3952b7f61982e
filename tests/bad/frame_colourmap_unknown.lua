-- expect: 2
-- stderr: frame_colourmap_unknown\.lua:5: sim:frame: .colourmap.: unknown colour map .jet. \(known: viridis, rdbu\)
-- Issue 31 item 7: the message did not name the key.
local sim = lamina.sim{ dt = 1e-3, domain = {0, 0, 1, 1}, cell = 0.1 }
sim:frame{ file = "out/bad/cm.png", width = 16, height = 16, colour = "speed", colourmap = "jet" }
