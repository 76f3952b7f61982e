-- Issue 33 item 4, one run guard: every way out of a run keeps the records
-- and leaves the sim able to step again. `way` picks how the run ends:
--   callback    sim:at's function raises an error at t = 0.0505
--   pin         a pin's velocity function raises one once t > 0.05
--   checkpoint  the checkpoint due at t = 0.05 cannot be written (its
--               folder is a regular file: refused even for root)
--   refused     a second run after courant was lowered: the Courant refusal
--   unstable    the body leaves the domain in the first step (engine failure)
--   signal      a run of hours that only a signal ends (run_guard.sh sends it)
-- caught = true runs it under pcall, prints the error, then steps once more
-- and prints "stepped on at t = ..." (before the guard the next step failed
-- with "called from inside a callback").
local way = lamina.param("way", "callback")
local caught = lamina.param("caught", false)
local out = lamina.param("out", "out/run_guard")
local sim = lamina.sim{basis = "linear", dt = 1e-3, domain = {0, 0, 1, 1}, cell = 0.1}
local el = lamina.elastic{rho = 1000, E = 1000, nu = 0.3}
local v = way == "unstable" and {1e3, 0} or {0.1, 0}
local b = sim:body{material = el, region = lamina.disk{center = {0.5, 0.5}, radius = 0.2},
                   velocity = v}
sim:record{file = out .. "/rec.csv", every = 0.01,
           values = {x = function() local x = b:com(); return x end}}
local t_end = 0.2
if way == "callback" then
  sim:at(0.0505, function() error("a callback failed") end)
elseif way == "pin" then
  b:pin{points = {1}, velocity = function(t)
    if t > 0.05 then error("the pin function failed at t = " .. t) end
    return 0.1, 0
  end}
elseif way == "checkpoint" then
  sim:checkpoint{file = out .. "/not_a_folder/ck.bin", at = 0.05}
elseif way == "refused" then
  sim:run{t_end = 0.05}
  sim.courant = 1e-3
elseif way == "signal" then
  sim:frame{file = out .. "/started.png", width = 16, height = 16}
  t_end = 1e4   -- hours: only a signal ends it
elseif way ~= "unstable" then
  error("way = " .. way .. " is none of callback, pin, checkpoint, refused, unstable, signal")
end
if not caught then
  sim:run{t_end = t_end}
  return
end
local ok, err = pcall(sim.run, sim, {t_end = t_end})
assert(not ok, "the run did not fail")
print("caught: " .. tostring(err))
if way == "pin" or way == "checkpoint" then
  -- the same function fails at the next step too, the checkpoint is still
  -- due: the step is taken and the same error raised, not "called from
  -- inside a callback"
  local ok2, err2 = pcall(sim.step, sim)
  local again = way == "pin" and "the pin function failed" or "sim:checkpoint: cannot write"
  assert(not ok2 and err2:find(again, 1, true), tostring(err2))
  print("stepped on at t = " .. sim.t .. " (" .. again .. " again)")
  return
elseif way == "unstable" then
  local ok2, err2 = pcall(sim.step, sim)   -- its particles are gone: it fails again
  assert(not ok2 and err2:find("simulation failed"), tostring(err2))
  print("stepped on at t = " .. sim.t .. " (the simulation failed again)")
  return
elseif way == "refused" then
  sim.courant = 1
end
sim:step()
print("stepped on at t = " .. sim.t)
