-- expect: 2
-- stderr: frame_contour_levels_alone\.lua:7: sim:frame: .contour_levels. needs contours = "pressure"
-- Issue 31 item 7: contour_levels was not looked at without contours, so
-- any value (true, "x", NaN) passed unseen. Now checked, and refused alone.
local sim = lamina.sim{ dt = 1e-3, domain = {0, 0, 1, 1}, cell = 0.1 }
assert(not pcall(sim.frame, sim, { file = "out/bad/cl.png", width = 16, height = 16, contour_levels = 0/0 }))
sim:frame{ file = "out/bad/cl.png", width = 16, height = 16, contour_levels = 12 }
