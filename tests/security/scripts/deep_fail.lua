-- Run by security.failed_write_leaves_no_folders (tests/CMakeLists.txt):
-- a frame whose folders can be created but whose file cannot (its name is
-- longer than any file system allows). Issue 18: a failed deep path left
-- 2048 created directories; the folders made for a failed write go again.
local sim = lamina.sim{ dt = 1e-3 }
local deep = "out/security/deep" .. string.rep("/d", 64)
sim:frame{ file = deep .. "/" .. string.rep("n", 300) .. ".png", width = 16, height = 16 }
