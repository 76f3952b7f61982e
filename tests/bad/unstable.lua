-- expect: 1
-- stderr: simulation failed: at t = .*particle [0-9]+ of body 1
-- stderr: likely cause: .*time step
-- Raising courant to let a far too large dt through: the run blows up and
-- stops at the first NaN or inverted particle with exit status 1.
local sim = lamina.sim{ cell = 0.05, dt = 0.2, courant = 100, boundary = "fixed" }
local m = lamina.elastic{ rho = 1000, E = 1000, nu = 0.3 }
sim:body{ material = m, region = lamina.disk{ center = {0.5, 0.5}, radius = 0.2 },
          velocity = function(x, y) return x - 0.5, 0 end }
sim:run{ t_end = 100 }
