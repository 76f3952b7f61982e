-- Run by security.memory_cap (issue 31 item 5): n simulations on a
-- 1000 x 1000 grid (~72 MB of engine arrays each, a small userdata to the
-- Lua collector), kept in a table or dropped as they are made.
local n = lamina.param("n", 2000)
local keep = lamina.param("keep", 1)
local kept = {}
for i = 1, n do
  local s = lamina.sim{ cell = 0.001, dt = 1e-4 }
  if keep == 1 then kept[i] = s end
end
print("made " .. n)
