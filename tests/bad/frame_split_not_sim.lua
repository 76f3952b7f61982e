-- expect: 2
-- stderr: frame_split_not_sim\.lua:7: sim:frame: 'split' must be a simulation \(lamina\.sim\), got number
-- The right half of a split frame shows another simulation, nothing else.
local sim = lamina.sim{ dt = 1e-3 }
local m = lamina.elastic{ rho = 1, E = 1, nu = 0.3 }
sim:body{ material = m, region = lamina.disk{ center = {0.5, 0.5}, radius = 0.2 } }
sim:frame{ file = "out/frame_split_not_sim.png", split = 3 }
