-- Run by security.memory_cap (issue 31 item 5): a simulation (~72 MB of
-- engine arrays) and then a Lua table that grows without end. The Lua heap
-- alone stays far below its own cap (--lua-mem, 1024 MB); together with
-- the engine's arrays it reaches the process's cap, which names both.
local s = lamina.sim{ cell = 0.001, dt = 1e-4 }
local t = {}
for i = 1, 1e9 do t[i] = ("x"):rep(64) .. i end
