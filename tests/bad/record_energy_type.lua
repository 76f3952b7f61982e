-- expect: 2
-- stderr: record_energy_type\.lua:6: sim:record: .energy. must be true or false \(got string\)
-- Issue 31 item 7: energy = "no" (any truth value) added the energy columns.
local sim = lamina.sim{ dt = 1e-3, domain = {0, 0, 1, 1}, cell = 0.1 }
sim:record{ energy = false }
sim:record{ energy = "no" }
