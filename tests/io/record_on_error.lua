-- A run ended by an error in a callback keeps its records (issue 19 item 2,
-- the first reproduced bug: the CSV was lost): rows every 0.01 to t = 0.05,
-- then a callback fails.
local sim = lamina.sim{basis = "linear", dt = 1e-3, domain = {0, 0, 1, 1}, cell = 0.1}
local el = lamina.elastic{rho = 1000, E = 1000, nu = 0.3}
local b = sim:body{material = el, region = lamina.disk{center = {0.5, 0.5}, radius = 0.2},
                   velocity = {0.1, 0}}
sim:record{file = lamina.param("csv", "out/record_on_error.csv"), every = 0.01,
           values = {x = function() local x = b:com(); return x end}}
sim:at(0.0505, function() error("a callback failed") end)
sim:run{t_end = 0.2}
