-- title: A figure made in a moment
-- source: issue 18 (a meta.json linked to /dev/zero was read for ever)
-- look: one small frame
local out = lamina.param("out", "out/security/quick")
local sim = lamina.sim{ dt = 1e-3 }
sim:frame{ file = out .. "/quick.png", width = 32, height = 32 }
lamina.report{ steps = sim.nstep }
