-- Two small elastic disks on a coarse grid: the scenario of the workbench
-- tests (tests/cli). A few hundred steps, well under a second.
--   t_end  how long it runs (the repl's interrupt test asks for much longer)
--   E      Young's modulus of both disks
--   fail   a value containing "yes": a Lua error after the report (a
--          failing run of a sweep)
--   out    the run's folder (lamina sweep passes it)
local t_end = lamina.param("t_end", 0.3)
E = lamina.param("E", 1000)
local fail = lamina.param("fail", "no")
local out = lamina.param("out", "out/cli")

sim = lamina.sim{ basis = "linear", domain = {0, 0, 1, 1}, cell = 0.1, dt = 1e-3 }
rubber = lamina.elastic{ rho = 1000, E = E, nu = 0.3 }
local a = sim:body{ material = rubber, ppc = 4, velocity = { 0.1,  0.1},
                    region = lamina.disk{ center = {0.3, 0.3}, radius = 0.15 } }
local b = sim:body{ material = rubber, ppc = 4, velocity = {-0.1, -0.1},
                    region = lamina.disk{ center = {0.7, 0.7}, radius = 0.15 } }
sim:at(0.1, function(s) rubber.E = 1.5 * E end)   -- a live change, logged
sim:run{ t_end = t_end }
local vx = a:velocity()
lamina.report{ steps = sim.nstep, vx = vx, energy = sim:energy().total }
if fail:find("yes") then
  error("deliberate failure (fail = " .. fail .. ")")
end
sim:frame{ file = out .. "/last.png", width = 64, height = 64 }
