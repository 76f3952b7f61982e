-- expect: 1
-- stderr: simulation failed: at t = 0\.128333 \(step 77\): particle 4042 of body 1 was compressed to zero or negative volume
-- stderr: with scheme = "usl", a node of tiny mass \(a surface particle on or just past a cell edge\) whose force USL divides by that mass: scheme = "musl" does not
-- A disk in rigid flight, stepping h/60 a step: its surface particles land
-- on cell edges, where a node gets 1e-16 of a particle's mass, and USL
-- divides the node's force by it ([T] §8.1; the dissertation's "division
-- by a very small grid mass", cured by the momentum form): the stress rises
-- from round-off (1e-13) and the run blows up at step 77 at any dt. The
-- message names that cause and the way out; the same run with scheme =
-- "musl" flies 300 steps stress-free (tests/physics/rigid_flight_edges.lua).
local h = 0.01
local sim = lamina.sim{ cell = h, dt = h / 6, scheme = "usl", basis = "linear" }
local m = lamina.elastic{ rho = 1000, E = 1000, nu = 0.3 }
sim:body{ material = m, velocity = {0.1, 0.1},
          region = lamina.disk{ center = {0.25, 0.25}, radius = 0.2 } }
sim:step(300)
