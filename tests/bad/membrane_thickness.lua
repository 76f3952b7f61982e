-- expect: 2
-- stderr: membrane_thickness\.lua:5: lamina\.membrane: thickness must be positive \(got 0\)
-- Zero or negative thickness is refused with the value.
local sim = lamina.sim{ cell = 0.1, dt = 1e-5 }
local m = lamina.membrane{ rho = 1, E = 1e4, thickness = 0 }
