-- expect: 2
-- stderr: frame_colour_unknown\.lua:7: sim:frame: colour = "temperature" is not one of "body" \| "vx" \| "vy" \| "sxx".*"pressure".*"membrane_stress"
-- Particles are coloured by body or by a field of the engine's table (docs/api.md "Particle fields"); others are named.
local sim = lamina.sim{ dt = 1e-3 }
local m = lamina.elastic{ rho = 1, E = 1, nu = 0.3 }
sim:body{ material = m, region = lamina.disk{ center = {0.5, 0.5}, radius = 0.2 } }
sim:frame{ file = "out/frame_colour_unknown.png", colour = "temperature" }
