-- expect: 2
-- stderr: record_field_unknown\.lua:7: sim:record: fields\.t: no field 'temperature' \(docs/api\.md, "Particle fields"\)
-- sim:record{fields} (issue 33 item 2): a field the engine's table lacks is named.
local sim = lamina.sim{ dt = 1e-3, domain = {0, 0, 1, 1}, cell = 0.1 }
local m = lamina.elastic{ rho = 1, E = 1, nu = 0.3 }
local b = sim:body{ material = m, region = lamina.disk{ center = {0.5, 0.5}, radius = 0.2 } }
sim:record{ fields = { t = {b, 1, "temperature"} } }
