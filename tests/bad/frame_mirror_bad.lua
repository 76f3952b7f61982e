-- expect: 2
-- stderr: frame_mirror_bad\.lua:7: sim:frame: mirror = "z" is not one of "x" \| "y" \| "xy"
-- Mirroring is about x, y or both.
local sim = lamina.sim{ dt = 1e-3 }
local m = lamina.elastic{ rho = 1, E = 1, nu = 0.3 }
sim:body{ material = m, region = lamina.disk{ center = {0.5, 0.5}, radius = 0.2 } }
sim:frame{ file = "out/frame_mirror_bad.png", mirror = "z" }
