-- expect: 2
-- stderr: mesh_malformed\.lua:6: lamina\.mesh: meshes/malformed\.obj:9: face corner 3 '9': names a vertex not defined before it
-- A malformed mesh file is refused naming the file, the line and what is
-- wrong (the reader's message, src/mpm/mesh3.c); nothing is made.
local sim = lamina.sim{ dim = 3, domain = {0, 0, 0, 1, 1, 1}, cell = 0.1, dt = 1e-3 }
local m = lamina.mesh{ file = "meshes/malformed.obj" }
