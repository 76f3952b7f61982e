-- expect: 2
-- args: --memory 256
-- stderr: sim3_memory_body\.lua:9: sim:body: memory limit 256 MB reached \(engine: 83 MB, lua: [0-9]+ MB, render: 0 MB; engine asked for 4512 MB more\)
-- A 3D body's particle arrays are charged to the one cap before they grow:
-- 27 points in each of 10^6 cells, 141 bytes a point at the doubling's
-- capacity (2^25), refused before anything is allocated.
local sim = lamina.sim{ dim = 3, domain = {0, 0, 0, 1, 1, 1}, cell = 0.01, dt = 1e-4 }
local rock = lamina.elastic{ rho = 1000, E = 1e6 }
sim:body{ material = rock, ppc = 27, region = lamina.box{ min = {0, 0, 0}, max = {1, 1, 1} } }
