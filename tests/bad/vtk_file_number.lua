-- expect: 2
-- stderr: vtk_file_number\.lua:6: sim:vtk: .file. must be a string \(got number\)
-- Issue 31 item 7: a number for file was turned into a name ("nan.pvd",
-- "1e+300.pvd"); every other writer refused it.
local sim = lamina.sim{ dt = 1e-3, domain = {0, 0, 1, 1}, cell = 0.1 }
sim:vtk{ file = 0/0, every = 1e-3 }
