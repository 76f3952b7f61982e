-- expect: 2
-- stderr: courant_usl\.lua:12: dt = 0\.035 is too large: Courant number dt\*c/h = 0\.81216. exceeds courant = 1 x 0\.7 for scheme = "usl"
-- stderr: use dt <= 0\.0301662
-- USL is less stable than MUSL ([T] §8.1: it divides each node's momentum
-- by its own mass): [T] Ch. 8's bar with one point per cell at the centres
-- first grows at dt c / h = 0.75 (docs/robustness.md), so the check scales
-- courant by 0.7 for USL. c = 1.16024 (tests/bad/courant.lua), h = 0.05:
-- Courant 0.812 passes MUSL's 1 and is refused here.
local sim = lamina.sim{ cell = 0.05, dt = 0.035, scheme = "usl" }
local m = lamina.elastic{ rho = 1000, E = 1000, nu = 0.3 }
sim:body{ material = m, region = lamina.disk{ center = {0.5, 0.5}, radius = 0.2 } }
sim:run{ t_end = 1 }
