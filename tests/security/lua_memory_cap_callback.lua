-- expect: 2
-- args: --lua-mem 32
-- stderr: Lua memory (reached its cap of|is capped at) 32 MB \(lamina run --lua-mem MB raises it\)
-- The cap holds inside a callback too (raised again by sim:run).
local sim = lamina.sim{ dt = 1e-3 }
local t = {}
sim:every(1e-3, function() for i = 1, 1e9 do t[#t + 1] = ("y"):rep(64) .. i end end)
sim:run{ t_end = 0.01 }
