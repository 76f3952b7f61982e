-- expect: 2
-- args: --out-root out/security/root
-- stderr: out_root\.lua:9: sim:frame: cannot write 'out/security/outside_root\.png': .*outside the output root '.*out/security/root'
-- lamina run --out-root DIR: files go inside DIR (relative names still
-- start from the working directory); the rest of the working directory
-- is outside.
local sim = lamina.sim{ dt = 1e-3 }
sim:frame{ file = "out/security/root/inside.png", width = 16, height = 16 }
sim:frame{ file = "out/security/outside_root.png", width = 16, height = 16 }
