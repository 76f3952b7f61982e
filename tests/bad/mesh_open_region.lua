-- expect: 2
-- stderr: mesh_open_region\.lua:9: sim:body: 'region': a region must be a closed mesh: meshes/open\.obj is not closed: the edge from vertex [0-9]+ to [0-9]+ is in 1 triangle
-- An open mesh has no inside: as a region it is refused naming the file and
-- an edge that only one triangle holds (as a membrane surface it is fine).
local sim = lamina.sim{ dim = 3, domain = {0, 0, 0, 2, 2, 2}, cell = 0.1, dt = 1e-3 }
local m = lamina.mesh{ file = "meshes/open.obj", translate = {0.5, 0.5, 0.5} }
assert(not m.closed)
local rock = lamina.elastic{ rho = 1000, E = 1e6, nu = 0.3 }
sim:body{ material = rock, region = m }
