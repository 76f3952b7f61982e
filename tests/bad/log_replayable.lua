-- expect: 0
-- stderr: sim\.gravity = \{0, -5\}
-- stderr: sim\.dt = 0\.0005$
-- stderr: material\.E = 2000$
-- A live change is logged as Lua that replays it (issue 20 item 5: a
-- gravity change was logged as "table: 0x..."): tables of numbers as
-- {a, b}, numbers with the fewest digits that read back exactly.
local sim = lamina.sim{dt = 1e-3}
local el = lamina.elastic{rho = 1000, E = 1000, nu = 0.3}
sim:body{material = el, region = lamina.disk{center = {0.5, 0.5}, radius = 0.2}}
sim:at(0.002, function(s) s.gravity = {0, -5}; s.dt = 5e-4; el.E = 2000 end)
sim:run{t_end = 0.005}
local c = lamina.changes()
assert(#c == 3 and c[1].value == "{0, -5}", "lamina.changes: " .. tostring(c[1] and c[1].value))
