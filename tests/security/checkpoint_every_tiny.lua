-- expect: 0
-- Issue 31, item 4: sim:checkpoint{every = 1e-300} hung (the next time was
-- counted up by adding 1e-300, which t absorbs). Every schedule's next time
-- is now computed (l_sim.c la_next_multiple): an interval below dt fires once
-- per step. An interval too small for the clock where it is set (t + every
-- == t, or more than 2^53 multiples to reach t) is refused at the call.
local sim = lamina.sim{ dt = 1e-3, domain = {0, 0, 1, 1}, cell = 0.1 }
local el = lamina.elastic{ rho = 1000, E = 1000, nu = 0.3 }
sim:body{ material = el, region = lamina.disk{ center = {0.5, 0.5}, radius = 0.2 } }
sim:checkpoint{ file = "out/security/every_tiny.ck", every = 1e-300 }
local n = 0
sim:every(1e-300, function() n = n + 1 end)
sim:run{ t_end = 0.01 }
assert(sim.nstep == 10 and n == 11, sim.nstep .. " steps, " .. n .. " calls")
-- at t = 0.01 the same intervals are below the clock's resolution
for _, call in ipairs{
  function() sim:checkpoint{ file = "out/security/every_tiny.ck", every = 1e-300 } end,
  function() sim:every(1e-300, function() end) end,
  function() sim:record{ every = 1e-300 } end,
  function() sim:vtk{ file = "out/security/every_tiny", every = 1e-300 } end,
} do
  local ok, err = pcall(call)
  assert(not ok and err:find("too small for the run's clock at t = 0.01", 1, true), tostring(err))
end
-- sim:at(NaN) never fired; it is refused
local ok, err = pcall(sim.at, sim, 0 / 0, function() end)
assert(not ok and err:find("must be a finite number", 1, true), tostring(err))
print("bounded")
