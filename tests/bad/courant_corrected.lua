-- expect: 2
-- stderr: courant_corrected\.lua:13: dt = 0\.035 is too large: Courant number dt\*c/h = 0\.81216. exceeds courant = 1 x 0\.63 for mass = "corrected"
-- stderr: use dt <= 0\.0271
-- mass = "corrected" (src/mpm/mass_corrected.c) makes the highest grid
-- mode faster: the 1-D bar first grows at dt c / h = 1.06 (linear, 9
-- points per cell) against 1.66 lumped (docs/robustness.md "Corrected
-- mass"), so the check scales courant by 0.63. c = 1.16024
-- (tests/bad/courant.lua), h = 0.05: Courant 0.812 passes the lumped
-- mass's 1 and is refused here.
local sim = lamina.sim{ cell = 0.05, dt = 0.035, mass = "corrected" }
local m = lamina.elastic{ rho = 1000, E = 1000, nu = 0.3 }
sim:body{ material = m, region = lamina.disk{ center = {0.5, 0.5}, radius = 0.2 } }
sim:run{ t_end = 1 }
