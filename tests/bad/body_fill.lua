-- expect: 2
-- stderr: body_fill\.lua:6: sim:body: 'fill' must be "centres" or "clipped" \(got exact\)
local sim = lamina.sim{ dt = 1e-3 }
local m = lamina.elastic{ rho = 1, E = 1, nu = 0.3 }
local r = lamina.disk{ center = {0.5, 0.5}, radius = 0.2 }
sim:body{ material = m, region = r, ppc = 4, fill = "exact" }
