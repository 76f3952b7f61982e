-- expect: 0
-- Issue 18, item 4: sim:every(1e-300, f) and sim:record{every = 1e-300}
-- hung (counting up to the next multiple). An interval below dt fires once
-- per step, as documented; so does one that is merely a bit smaller.
local sim = lamina.sim{ dt = 1e-3 }
local el = lamina.elastic{ rho = 1000, E = 1000, nu = 0.3 }
sim:body{ material = el, region = lamina.disk{ center = {0.5, 0.5}, radius = 0.2 } }
local n1, n2, n3 = 0, 0, 0
sim:every(1e-300, function() n1 = n1 + 1 end)
sim:every(4e-4, function() n2 = n2 + 1 end)
sim:every(5e-324, function() n3 = n3 + 1 end)   -- the smallest double
local rec = sim:record{ every = 1e-300 }
sim:run{ t_end = 0.01 }
assert(sim.nstep == 10, sim.nstep)
assert(n1 == 11 and n3 == 11, ("fired %d and %d times over 10 steps"):format(n1, n3))
assert(n2 == 11, n2)
assert(#rec == 11, #rec)
print("once per step")
