-- expect: 2
-- stderr: velocity_nan\.lua:14: sim:body: 'velocity' must be two finite numbers \(got \{1\.0, -?nan\}\)
-- Found by fuzzing (tests/fuzz, fuzz_lua): a body's velocity {1, 0/0} was
-- accepted; a step later every position was NaN, the gas density turned a
-- NaN into a cell index (undefined behaviour, UBSan) and the failure was
-- blamed on the time step. Pairs must be finite numbers (every pair of the
-- API), and so must what a velocity function returns.
local sim = lamina.sim{ dt = 1e-3, domain = {0, 0, 1, 1}, cell = 0.05 }
local gas = lamina.gas{ rho = 1, e = 1, density = "cell" }
local disk = lamina.disk{ center = {0.5, 0.5}, radius = 0.25 }
local ok, err = pcall(sim.body, sim, { material = gas, region = disk,
                                       velocity = function() return 0, 1/0 end })
assert(not ok and err:find("velocity function must return two finite numbers"), tostring(err))
sim:body{ material = gas, region = disk, ppc = 9, velocity = {1, 0/0} }
