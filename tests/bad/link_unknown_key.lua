-- expect: 2
-- stderr: link_unknown_key\.lua:8: sim:link: unknown key 'stifness'
-- A misspelt key of sim:link is refused by name, at the script's line.
local sim = lamina.sim{ dt = 1e-4 }
local m = lamina.elastic{ rho = 1000, E = 1e6 }
local a = sim:body{ material = m, region = lamina.disk{ center = {0.3, 0.5}, radius = 0.1 } }
local b = sim:body{ material = m, region = lamina.disk{ center = {0.7, 0.5}, radius = 0.1 } }
sim:link{ a = {a, 1}, b = {b, 1}, stifness = 1e3 }
