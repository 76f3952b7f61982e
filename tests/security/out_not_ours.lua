-- expect: 0
-- Issue 31, item 1: a script replaced any regular file under the output root
-- (conftest.py, a Makefile). Now an existing file is replaced only when
-- lamina wrote it (ROOT/.lamina-outputs, or a PNG/checkpoint carrying
-- lamina's provenance), and a link as the target is refused.
-- tests/CMakeLists.txt writes out/security/theirs/conftest.py (not lamina's)
-- and the link out/security/theirs/link.csv -> conftest.py.
local sim = lamina.sim{ dt = 1e-3, domain = {0, 0, 1, 1}, cell = 0.1 }
local ok, err = pcall(sim.record, sim, { file = "out/security/theirs/conftest.py", energy = true })
assert(not ok and err:find("it exists and lamina did not write it", 1, true), tostring(err))
ok, err = pcall(sim.frame, sim, { file = "out/security/theirs/conftest.py", width = 16, height = 16 })
assert(not ok and err:find("lamina did not write it", 1, true), tostring(err))
ok, err = pcall(sim.checkpoint, sim, { file = "out/security/theirs/conftest.py", at = 1 })
assert(not ok and err:find("lamina did not write it", 1, true), tostring(err))
ok, err = pcall(sim.record, sim, { file = "out/security/theirs/link.csv", energy = true })
assert(not ok and err:find("it is a symbolic link", 1, true), tostring(err))
-- lamina's own outputs are replaced freely: twice in this run (and again
-- when the test runs a second time, from the list of outputs)
for _ = 1, 2 do
  sim:frame{ file = "out/security/theirs/ours.png", width = 16, height = 16 }
  lamina.plot{ file = "out/security/theirs/ours_plot.png", csv = true,
               series = { { x = {0, 1}, y = {0, 1} } } }
end
local rec = sim:record{ file = "out/security/theirs/ours.csv", energy = true }
sim:run{ t_end = 2e-3 }
rec:write()
rec:write()
print("ok")
