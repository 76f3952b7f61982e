-- expect: 2
-- stderr: Courant number dt\*c/h = 1\.06667 exceeds courant = 1
-- stderr: membrane 'sheet' \(body 1\); its tension acts along segments, stable to dt\*c/h = 0\.75
-- A membrane with segment forces is stable only to dt c / h = 0.75
-- (measured, docs/robustness.md): dt = 0.8 h / c is refused, naming it.
local sim = lamina.sim{domain = {0, 0, 2, 1}, cell = 0.05, dt = 0.8 * 0.05 / 100}
local mat = lamina.membrane{rho = 1000, E = 1e7, nu = 0, thickness = 0.005, law = "uniaxial"}
sim:membrane{material = mat, name = "sheet", force = "segment", spacing = 0.05 / 3,
             curve = lamina.segment{from = {0.2, 0.5}, to = {1.8, 0.5}}}
sim:run{t_end = 0.01}
