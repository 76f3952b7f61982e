-- expect: 2
-- stderr: gravity_nan\.lua:8: lamina\.sim: 'gravity' must be two finite numbers
-- Issue 18, unclear messages: gravity = {0, 0/0} was accepted, then blamed
-- on the time step. It is refused, naming the key (and so is sim.gravity).
local s = lamina.sim{ dt = 1e-3 }
local ok, err = pcall(function() s.gravity = {0, 1/0} end)
assert(not ok and err:find("sim.gravity must be two finite numbers"), tostring(err))
lamina.sim{ dt = 1e-3, gravity = {0, 0/0} }
