-- Checkpoint and restart (issue 20 item 2; tests/io/restart.sh drives it):
-- the dog-bone at cell 0.4 with gas splitting (the particle count changes
-- during the run), a live setting changed by a callback (pic) and a
-- recorder, checkpointed every 0.05.
-- Prints the state hash at the end; restart.sh compares an uninterrupted
-- run with one killed by SIGKILL after a checkpoint and resumed.
local t_end = lamina.param("t_end", 0.2)
local out = lamina.param("out", "out/restart/a")
local slow = lamina.param("slow", 0)       -- seconds of busy wait per 1e-3: time to kill
local dog = require("dogbone")
local sim, gas, mem = dog.setup(0.4, { split = 60 })
local n0 = #gas
sim:record{ file = out .. ".csv", every = 0.01, values = {
  p = function() return gas:pressure(mem) end, n = function() return #gas end } }
sim:at(0.03, function(s) s.pic = 0.001 end)
sim:checkpoint{ file = lamina.param("ck", out .. ".ckpt"), every = 0.05 }
if slow > 0 then
  sim:every(1e-3, function()
    local t0 = lamina.clock()
    while lamina.clock() - t0 < slow do end
  end)
end
sim:run{ t_end = t_end }
print(string.format("RESULT t %.6f step %d gas %d (from %d) hash %s", sim.t, sim.nstep, #gas, n0,
                    sim:hash()))
