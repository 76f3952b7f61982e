-- expect: 2
-- stderr: courant\.lua:9: dt = 0\.05 is too large: Courant number
-- stderr: use dt <= 0\.0430946
-- A dt above the Courant limit (docs/physics.md §5) is refused with the limit.
-- c = sqrt(E(1-nu)/((1+nu)(1-2nu)rho)) = 1.16024 for E = 1000, rho = 1000.
local sim = lamina.sim{ cell = 0.05, dt = 0.05 }
local m = lamina.elastic{ rho = 1000, E = 1000, nu = 0.3 }
sim:body{ material = m, region = lamina.disk{ center = {0.5, 0.5}, radius = 0.2 } }
sim:run{ t_end = 1 }
