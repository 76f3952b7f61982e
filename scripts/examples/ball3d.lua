-- An elastic ball dropped on a floor, in 3D (issue 34; docs/3d.md).
-- What to look for: the ball falls, lands on the fixed face z0 near
-- t = 0.09, flattens and rebounds most of the way up (the rest of the
-- energy rings on in the ball as strain and vibration); the total energy (kinetic + strain + potential) dips while it touches the
-- floor and comes back to within 1 % of its start (tests/physics/
-- sim3_ball_drop.lua checks this scene against the axisymmetric 2D run).
-- Writes out/ball3d/energy.csv (the energies and the centre's height every
-- 5 ms) and out/ball3d/ball.pvd (the particles and the grid every 30 ms, for
-- ParaView). Runs in a few seconds: lamina run scripts/examples/ball3d.lua
local cell  = lamina.param("cell", 0.025)
local t_end = lamina.param("t_end", 0.3)
local out   = lamina.param("out", "out/ball3d")
local sim = lamina.sim{ dim = 3, domain = {0, 0, 0, 0.4, 0.4, 0.4}, cell = cell, dt = 5e-4,
                        gravity = {0, 0, -9.81},
                        boundary = { x0 = "free", x1 = "free", y0 = "free", y1 = "free",
                                     z0 = "fixed", z1 = "free" } }
local rubber = lamina.elastic{ rho = 1000, E = 1e5, nu = 0.3 }   -- no `plane` in 3D
local ball = sim:body{ material = rubber, ppc = 8, velocity = {0, 0, -1}, name = "ball",
                       region = lamina.ball{ center = {0.2, 0.2, 0.2}, radius = 0.1 } }
print(string.format("%d particles, %.3f kg; Courant number %.3f", #ball, ball:mass(),
                    sim:courant_number()))
sim:record{ file = out .. "/energy.csv", every = 0.005, energy = true,
            values = { z = function() local _, _, z = ball:com() return z end } }
sim:vtk{ file = out .. "/ball", every = 0.03 }
local e0 = sim:energy().total
local zlow, apex = 1, 0
sim:every(0.03, function(s)
  local _, _, z = ball:com()
  local _, _, vz = ball:velocity()
  local e = s:energy()
  zlow = math.min(zlow, z)
  if z > zlow then apex = math.max(apex, z) end
  print(string.format("t = %.2f  centre z = %.4f m  vz = %+.3f m/s  kinetic %.4f  strain %.4f  "
                      .. "total/start %.4f", s.t, z, vz, e.kinetic, e.strain, e.total / e0))
end)
sim:run{ t_end = t_end }
print(string.format("lowest centre %.4f m, apex after the bounce %.4f m (thrown from 0.2 at 1 m/s: "
                    .. "%.4f without losses)", zlow, apex, 0.2 + 1 / (2 * 9.81)))
