-- expect: 2
-- stderr: sim:vtk: every must be positive
local sim = lamina.sim{domain = {0, 0, 1, 1}, cell = 0.1, dt = 1e-4}
local ok, err = pcall(sim.vtk, sim, {})
assert(not ok and err:find("'file' %(a path without extension%) is required"), err)
ok, err = pcall(sim.vtk, sim, {file = "out/a\0b"})
assert(not ok and err:find("NUL byte"), err)
ok, err = pcall(sim.vtk, sim, {file = "out/x", evry = 1})
assert(not ok and err:find("unknown key 'evry'"), err)
sim:vtk{file = "out/vtk_bad/run", every = 0}
