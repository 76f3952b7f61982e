-- expect: 0
-- Issue 18, crashes (exit 139): sim:record{points = "x"}, values = 5,
-- angle = true walked a non-table with lua_next. Each is a clear error now.
local sim = lamina.sim{ dt = 1e-3 }
local el = lamina.elastic{ rho = 1000, E = 1000, nu = 0.3 }
sim:body{ material = el, region = lamina.disk{ center = {0.5, 0.5}, radius = 0.2 } }
for key, v in pairs{ points = "x", values = 5, angle = true } do
  local ok, err = pcall(sim.record, sim, { [key] = v })
  assert(not ok and err:find("'" .. key .. "' must be a table of named entries"), tostring(err))
end
print("no crash")
