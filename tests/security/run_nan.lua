-- expect: 2
-- stderr: run_nan\.lua:7: sim:run: t_end must be a finite number \(got (-?nan|-?inf)\)
-- Issue 18, wrong answers: sim:run{t_end = 0/0} exited 0 after 0 steps.
local sim = lamina.sim{ dt = 1e-3 }
local ok, err = pcall(sim.run, sim, { t_end = 1/0 })
assert(not ok and err:find("finite"), tostring(err))
sim:run{ t_end = 0/0 }
