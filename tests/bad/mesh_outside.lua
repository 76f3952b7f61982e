-- expect: 2
-- stderr: mesh_outside\.lua:7: lamina\.mesh: cannot read '\.\./physics/meshes/cube\.stl': it resolves to '.*/tests/physics/meshes/cube\.stl', outside the script's folder '.*/tests/bad' and the output root
-- A mesh file is untrusted input's: read only from the script's folder or the
-- output root (docs/security.md "Inputs"); a name leading out of both is
-- refused before anything is read, naming where it resolves.
local sim = lamina.sim{ dim = 3, domain = {0, 0, 0, 1, 1, 1}, cell = 0.1, dt = 1e-3 }
local cube = lamina.mesh{ file = "../physics/meshes/cube.stl" }
