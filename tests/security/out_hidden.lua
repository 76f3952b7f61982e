-- expect: 2
-- stderr: out_hidden\.lua:15: sim:frame: cannot write 'out/security/\.git/x\.png': a name in it starts with a dot
-- Issue 31, item 1: no output name component may start with a dot: a script
-- run from a home folder wrote .bashrc, and .git/hooks run on the next
-- commit. "." and ".." only navigate and stay allowed (resolved against the
-- real folders). lamina's own list of outputs (.lamina-outputs) is hidden so
-- no script can write it.
local sim = lamina.sim{ dt = 1e-3 }
for _, f in ipairs{ ".bashrc", "out/.hidden/x.csv", ".lamina-outputs", "out/security/..x.png" } do
  local ok, err = pcall(sim.record, sim, { file = f, energy = true })
  assert(not ok and err:find("starts with a dot", 1, true), f .. ": " .. tostring(err))
end
sim:frame{ file = "out/security/./dot_ok.png", width = 16, height = 16 }
sim:frame{ file = "./out/security/root/../dot_ok.png", width = 16, height = 16 }
sim:frame{ file = "out/security/.git/x.png", width = 16, height = 16 }
