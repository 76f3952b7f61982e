-- expect: 2
-- stderr: out_symlink\.lua:7: sim:frame: cannot write 'out/security/to_slash/tmp/lamina_x\.png': it resolves to '/tmp/lamina_x\.png', outside the output root
-- Issue 18, item 2: a path through a symbolic link that leaves the output
-- root is refused (the link is resolved before anything is created).
-- tests/CMakeLists.txt makes out/security/to_slash -> /.
local sim = lamina.sim{ dt = 1e-3 }
sim:frame{ file = "out/security/to_slash/tmp/lamina_x.png", width = 16, height = 16 }
