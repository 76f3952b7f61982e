-- expect: 2
-- stderr: bad_material\.lua:4: lamina\.elastic: nu must lie in \(-1, 0\.5\) \(got 0\.5\)
-- A physically impossible parameter is rejected with its value.
local m = lamina.elastic{ rho = 1, E = 1000, nu = 0.5 }
