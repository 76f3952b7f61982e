-- expect: 2
-- stderr: mesh_pin_edges_closed\.lua:9: sim:membrane: pin = "edges": the mesh is closed and has no edges
-- pin = "edges" on a lamina.mesh surface holds the points on its rim (the
-- edges only one triangle holds); a closed mesh has none: refused by name.
local sim = lamina.sim{ dim = 3, domain = {0, 0, 0, 1, 1, 1}, cell = 0.1, dt = 1e-3 }
local skin = lamina.membrane{ rho = 1000, E = 1e6, nu = 0.3, thickness = 1e-3, law = "plane_stress" }
local tet = lamina.mesh{ file = "meshes/tetra.obj", scale = 0.5, translate = {0.2, 0.2, 0.2} }
assert(tet.closed)
sim:membrane{ material = skin, spacing = 0.05, pin = "edges", surface = tet }
