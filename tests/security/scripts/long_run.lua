-- Run by security.signal_*_keeps_records (signal.sh) and
-- security.sweep_term_stops_children (sweep_term.sh): a long run that records
-- every step; its first frame tells the test that the run has begun.
local sim = lamina.sim{ dt = 1e-4 }
local el = lamina.elastic{ rho = 1000, E = 1000, nu = 0.3 }
sim:body{ material = el, region = lamina.disk{ center = {0.5, 0.5}, radius = 0.2 } }
local out = lamina.param("out", "out/security/signal")
lamina.param("k", 1)   -- what `lamina sweep` varies (security.sweep_term_stops_children)
sim:record{ file = out .. "/rec.csv", energy = true }
sim:frame{ file = out .. "/started.png", width = 16, height = 16 }
sim:run{ t_end = 1e4 }   -- hours: only a signal ends it
