-- A gas-filled balloon dropped on the floor: the default scenario of
-- `bash .ci/main` (issue 32 item 2), the papers' subject in one picture -
-- a membrane holding a gas ([F] §4.3, [N] §8), its normals found every
-- step ([N]), the gas pushing on it ([F] eqs 9-11).
-- What to look for: the balloon falls, flattens on the floor, the gas
-- pressure rising where it is squeezed (colour), and bounces; the
-- membrane's phi = 1 contour runs through its points (bold) with the
-- levels 0, 0.5 and 1.5 (thin, [N] Figs 12-16) and its normals point out;
-- no gas crosses the membrane (printed at the end).
-- Set-up: a half model (x >= 0, the left side a symmetry wall, drawn
-- mirrored), radius 0.4, 90 membrane points, isosurface normals ([N]),
-- gas at p = 100 (sound speed 11.8), dropped at 3 m/s under gravity onto a
-- frictionless floor (a "symmetry" side: the wall holds the normal
-- velocity only).
local cell  = lamina.param("cell", 0.05)
local t_end = lamina.param("t_end", 0.6)
local out   = lamina.param("out", "out/balloon")
local every = lamina.param("every", 0.02)

local sim = lamina.sim{ domain = {0, 0, 0.8, 1.4}, cell = cell, dt = 1e-3 * cell,   -- Courant 0.88 on the membrane (its segment wave speed)
                        gravity = {0, -9.81},
                        boundary = { left = "symmetry", bottom = "symmetry",
                                     right = "fixed", top = "fixed" } }
local air = lamina.gas{ rho = 1, p = 100, gamma = 1.4, mu = 0.2 }
local skin = lamina.membrane{ rho = 0.5, E = 2e5, nu = 0.3, thickness = 0.02,
                              law = "plane_stress" }
local centre, radius = {0, 0.85}, 0.4
local gas = sim:body{ material = air, ppc = 16, name = "gas", fill = "clipped",
                      velocity = {0, -3},
                      region = lamina.disk{ center = centre, radius = radius } }
local mem = sim:membrane{ material = skin, count = 90, name = "balloon", normals = "isosurface",
                          velocity = {0, -3},
                          curve = lamina.arc{ center = centre, radius = radius,
                                              from = 90, to = -90 } }

local escaped = 0
sim:every(every, function(s)
  escaped = math.max(escaped, mem:escaped(gas))
  s:frame{ file = string.format("%s/frame_%06d.png", out, s.nstep), width = 640, height = 560,
           mirror = "x", colour = "pressure", colour_bodies = {gas}, range = {60, 180}, colourmap = "viridis",
           discs = "spacing", title = string.format("balloon dropped on the floor, t = %.2f", s.t) }
end)
sim:run{ t_end = t_end }

print(string.format("t = %.3f  steps = %d  particles = %d", sim.t, sim.nstep, sim.n))
print(string.format("gas pressure %.1f, balloon centre height %.3f, velocity %.3f",
                    gas:pressure(), select(2, gas:com()), select(2, gas:velocity())))
print(string.format("gas points outside the membrane: %d", escaped))
