-- expect: 2
-- args: --memory 256
-- stderr: sim3_memory_membrane\.lua:9: sim:membrane: memory limit 256 MB reached \(engine: [0-9]+ MB, lua: [0-9]+ MB, render: 0 MB; engine asked for [0-9]+ MB more\)
-- A 3D membrane's points are charged to the one cap with the particles,
-- before the sampler allocates: a sphere of radius 0.45 at spacing 3e-4
-- (about 2.8e7 points, 215 bytes each at the doubling's capacity) is refused.
local sim = lamina.sim{ dim = 3, domain = {0, 0, 0, 1, 1, 1}, cell = 0.01, dt = 1e-4 }
local skin = lamina.membrane{ rho = 1000, E = 1e6, nu = 0.3, thickness = 1e-3, law = "plane_stress" }
sim:membrane{ material = skin, spacing = 3e-4, surface = lamina.sphere{ center = {0.5, 0.5, 0.5}, radius = 0.45 } }
