-- expect: 2
-- stderr: out_device\.lua:9: sim:frame: cannot write '/dev/null'
-- Issue 18, item 2: device files are no target (rename(2) over /dev/null,
-- as root, would replace it). Outside the root it is refused as such; a
-- folder inside it is refused as not a regular file.
local sim = lamina.sim{ dt = 1e-3 }
local ok, err = pcall(sim.frame, sim, { file = "out/security", width = 16, height = 16 })
assert(not ok and err:find("is not a regular file"), tostring(err))
sim:frame{ file = "/dev/null", width = 16, height = 16 }
