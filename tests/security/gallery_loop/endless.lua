-- title: A script that never ends
-- source: issue 18 (a gallery script with an endless loop hung the gallery)
-- look: nothing; lamina gallery --timeout stops it
local out = lamina.param("out", "out/security/endless")
local sim = lamina.sim{ dt = 1e-3 }
sim:frame{ file = out .. "/started.png", width = 16, height = 16 }
while true do end
