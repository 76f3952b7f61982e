-- Run by security.frame_oom_names_size under a small address-space limit:
-- the largest frame lamina allows (16384 x 16384, 1 GB of pixels) cannot be
-- made, and the error says which size (issue 18: "out of memory" alone).
local sim = lamina.sim{ dt = 1e-3 }
sim:frame{ file = "out/security/huge.png", width = 16384, height = 16384 }
