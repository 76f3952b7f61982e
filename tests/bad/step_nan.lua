-- expect: 2
-- stderr: step_nan\.lua:7: sim:step: n must be a whole number from 0 to 1e12 \(got -?nan\)
-- Issue 31 item 7: sim:step(NaN) said "bad argument #1 to step (number has
-- no integer representation)"; sim:step(1e18) ran for ever (now capped).
local sim = lamina.sim{ dt = 1e-3, domain = {0, 0, 1, 1}, cell = 0.1 }
assert(not pcall(sim.step, sim, 1e18))
sim:step(0/0)
