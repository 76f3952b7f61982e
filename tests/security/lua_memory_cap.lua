-- expect: 2
-- args: --lua-mem 32
-- stderr: lua_memory_cap\.lua: the script's Lua memory reached its cap of 32 MB \(lamina run --lua-mem MB raises it\)
-- Issue 18, item 3: no Lua memory cap. A script that grows without end
-- stops at the cap (default 1024 MB, here 32) with a message naming it.
local t = {}
for i = 1, 1e9 do t[i] = ("x"):rep(64) .. i end
