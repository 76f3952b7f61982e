-- expect: 2
-- stderr: frame_range_equal\.lua:8: sim:frame: 'range' must have max > min \(got \{1\.0+, 1\.0+\}\)
-- Issue 18, unclear messages: range = {1, 1} printed "invalid option '%g'
-- to 'lua_pushfstring'" (Lua's formatter knows no %g).
local sim = lamina.sim{ dt = 1e-3 }
local el = lamina.elastic{ rho = 1000, E = 1000, nu = 0.3 }
sim:body{ material = el, region = lamina.disk{ center = {0.5, 0.5}, radius = 0.2 } }
sim:frame{ file = "out/security/range.png", width = 16, height = 16, colour = "speed",
           range = {1, 1} }
