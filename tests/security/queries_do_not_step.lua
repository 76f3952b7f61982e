-- expect: 0
-- Queries do not advance the simulation (issue 18, wrong answers; issue 19
-- item 5): sim:courant() and sim:pic() used to take a step through a
-- __call on every number. The count is sim.nstep, sim:step(n) the method,
-- sim:courant_number() the Courant query; calling a number field is an
-- ordinary Lua error again, naming the field.
local sim = lamina.sim{dt = 1e-3}
local el = lamina.elastic{rho = 1000, E = 1000, nu = 0.3}
sim:body{material = el, region = lamina.disk{center = {0.5, 0.5}, radius = 0.2}}
assert(sim.nstep == 0)
local cn, c = sim:courant_number()
assert(cn > 0 and c > 0 and sim.nstep == 0, "courant_number stepped")
for _, q in ipairs{"courant", "pic", "dt", "nstep"} do
  local ok, err = pcall(function() return sim[q](sim) end)
  assert(not ok and err:find("attempt to call a number value"), q .. ": " .. tostring(err))
  assert(sim.nstep == 0, "sim:" .. q .. "() advanced the simulation")
end
sim:step(3)
assert(sim.nstep == 3 and type(sim.step) == "function")
print("queries do not step; sim.nstep = " .. sim.nstep)
