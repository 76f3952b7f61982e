-- expect: 2
-- stderr: record_field_kind\.lua:8: sim:record: fields\.tip: body 1 has no field 'tension' \(not a quantity of its kind\)
-- sim:record{fields} (issue 33 item 2): a field the body's kind does not
-- have (a solid's tension) is refused by name, not recorded as zeros.
local sim = lamina.sim{ dt = 1e-3, domain = {0, 0, 1, 1}, cell = 0.1 }
local m = lamina.elastic{ rho = 1, E = 1, nu = 0.3 }
local b = sim:body{ material = m, region = lamina.disk{ center = {0.5, 0.5}, radius = 0.2 } }
sim:record{ fields = { tip = {b, -1, "tension"} } }
