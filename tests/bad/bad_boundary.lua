-- expect: 2
-- stderr: bad_boundary\.lua:3: lamina\.sim: left = "sticky" is not one of "fixed" \| "symmetry" \| "free"
local sim = lamina.sim{ dt = 1e-3, boundary = { left = "sticky" } }
