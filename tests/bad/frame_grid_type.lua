-- expect: 2
-- stderr: frame_grid_type\.lua:7: sim:frame: .grid. must be true or false
-- Issue 31 item 7: sim:frame took any value for grid (a string, a number,
-- a function: all meant true). true (the default) or false.
local sim = lamina.sim{ dt = 1e-3, domain = {0, 0, 1, 1}, cell = 0.1 }
sim:frame{ file = "out/bad/frame_grid_ok.png", width = 16, height = 16, grid = false }
sim:frame{ file = "out/bad/frame_grid.png", width = 16, height = 16, grid = "no" }
