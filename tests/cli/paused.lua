-- A scenario meant for the repl: it runs a first stretch, pauses for a
-- look (lamina.pause() does nothing under `lamina run`), then goes on.
local sim = lamina.sim{ basis = "linear", domain = {0, 0, 1, 1}, cell = 0.1, dt = 1e-3 }
rubber = lamina.elastic{ rho = 1000, E = 1000, nu = 0.3 }
sim:body{ material = rubber, ppc = 4, velocity = {0.1, 0},
          region = lamina.disk{ center = {0.4, 0.5}, radius = 0.15 } }
sim:run{ t_end = 0.05 }
local note = "after the first run"
lamina.pause()
sim:run{ t_end = 0.1 }
print("resumed", sim.nstep, rubber.E)
