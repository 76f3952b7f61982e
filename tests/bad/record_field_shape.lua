-- expect: 2
-- stderr: record_field_shape\.lua:7: sim:record: fields\.p must be \{body, index, field\}
-- sim:record{fields} (issue 33 item 2): {body, index} without the field is named.
local sim = lamina.sim{ dt = 1e-3, domain = {0, 0, 1, 1}, cell = 0.1 }
local m = lamina.elastic{ rho = 1, E = 1, nu = 0.3 }
local b = sim:body{ material = m, region = lamina.disk{ center = {0.5, 0.5}, radius = 0.2 } }
sim:record{ fields = { p = {b, 1} } }
