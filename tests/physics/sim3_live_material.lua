-- A live material change reaches a 3D run (issue 34 item 1; l_material.c's
-- set_everywhere, as in 2D issue 33 item 1): mat.E doubled at t = 0.005
-- from a callback. Checks: the dilatational speed the Courant check reads
-- grows by sqrt(2) (to rounding); the change is logged at its time and step
-- (lamina.changes()); the same script twice gives the same state (the
-- change applies at the same step boundary), which differs from the run
-- without the change (it took effect).
local function run(change)
  local sim = lamina.sim{ dim = 3, domain = {0, 0, 0, 1, 1, 1}, cell = 0.1, dt = 1e-3,
                          gravity = {0, 0, -9.81} }
  local m = lamina.elastic{ rho = 1000, E = 1e6, nu = 0.3 }
  sim:body{ material = m, velocity = {0.2, 0, -0.5},
            region = lamina.ball{ center = {0.5, 0.5, 0.35}, radius = 0.2 } }
  local _, c0 = sim:courant_number()
  if change then sim:at(0.005, function() m.E = 2e6 end) end
  sim:run{ t_end = 0.05 }
  local _, c1 = sim:courant_number()
  return sim:hash(), c1 / c0
end
local h1, r1 = run(true)
local h2 = run(true)
local h0, r0 = run(false)
local log = lamina.changes()
print(string.format("wave speed ratio %.15f (sqrt 2 = %.15f); hashes %s %s, unchanged %s; "
  .. "logged %s = %s at t = %g, step %d", r1, math.sqrt(2), h1, h2, h0, log[1].what,
  log[1].value, log[1].t, log[1].step))
assert(math.abs(r1 - math.sqrt(2)) <= 1e-14, "the 3D copy did not take the change: " .. r1)
assert(r0 == 1, "without the change the speed moved: " .. r0)
assert(h1 == h2 and h1 ~= h0, "the change is not deterministic or had no effect")
assert(#log == 2 and log[1].what == "material.E" and log[1].step == 5 and
       math.abs(log[1].t - 0.005) < 1e-12, "the change is not logged at t = 0.005, step 5")
