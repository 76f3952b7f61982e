-- Run by security.stale_temps (stale_temps.sh): one frame into `out`.
local out = lamina.param("out", "out/security/stale")
local sim = lamina.sim{ dt = 1e-3 }
sim:frame{ file = out .. "/frame.png", width = 16, height = 16 }
