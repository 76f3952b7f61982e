-- expect: 2
-- stderr: out_nul\.lua:7: sim:frame: cannot write 'out/security/a\\0b\.png': the file name contains a NUL byte
-- Issue 18: file = "a\0b.png" wrote "a". A NUL byte in a file name is refused.
local sim = lamina.sim{ dt = 1e-3 }
local ok, err = pcall(sim.record, sim, { file = "out/security/r\0.csv" })
assert(not ok and err:find("NUL byte"), tostring(err))
sim:frame{ file = "out/security/a\0b.png", width = 16, height = 16 }
