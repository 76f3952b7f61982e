-- expect: 0
-- Issue 18, item 1: the metatables of lamina's objects are protected.
-- getmetatable(s).__gc(s) inside a callback, `local x <close> = s` and __gc
-- on a polygon or a recorder gave null dereferences and use-after-free.
local sim = lamina.sim{ dt = 1e-3 }
local el = lamina.elastic{ rho = 1000, E = 1000, nu = 0.3 }
local disk = lamina.disk{ center = {0.5, 0.5}, radius = 0.2 }
local poly = lamina.polygon{ {0.1, 0.1}, {0.3, 0.1}, {0.2, 0.3} }
local body = sim:body{ material = el, region = disk }
local rec = sim:record{ energy = true }
local arc = lamina.arc{ center = {0.5, 0.5}, radius = 0.1, from = 0, to = 90 }
local fig = lamina.figure{ width = 32, height = 32 }
local objects = { sim = sim, material = el, disk = disk, polygon = poly, body = body,
                  recorder = rec, arc = arc, figure = fig }
for what, o in pairs(objects) do
  assert(getmetatable(o) == "locked", what .. ": metatable reachable")
  local ok, err = pcall(setmetatable, o, {})
  assert(not ok, what .. ": setmetatable succeeded")
  ok, err = pcall(function() local x <close> = o end)
  assert(not ok and err:find("non%-closable"), what .. ": <close> accepted: " .. tostring(err))
end
-- strings' metatable too (string methods still work)
assert(getmetatable("") == "locked" and ("abc"):upper() == "ABC")
-- the objects still work after all that
sim:every(1e-3, function(s) assert(getmetatable(s) == "locked") end)
sim:run{ t_end = 3e-3 }
assert(#rec == 4 and poly:contains(0.2, 0.15) and sim.nstep == 3)
print("metatables locked")
