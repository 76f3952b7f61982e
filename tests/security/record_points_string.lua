-- expect: 2
-- stderr: record_points_string\.lua:5: sim:record: 'points' must be a table of named entries \(got string\)
-- Issue 18, crashes: sim:record{points = "x"} ended in a segmentation fault.
local sim = lamina.sim{ dt = 1e-3 }
sim:record{ points = "x" }
