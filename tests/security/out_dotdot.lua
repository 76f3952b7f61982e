-- expect: 2
-- stderr: out_dotdot\.lua:10: sim:frame: cannot write 'out/\.\./\.\./\.\./x\.png': it resolves to '.*', outside the output root
-- Issue 18, item 2: frames went to ../../x.png. A path that leaves the
-- working directory through ".." is refused, naming it; nothing is written.
local sim = lamina.sim{ dt = 1e-3 }
local el = lamina.elastic{ rho = 1000, E = 1000, nu = 0.3 }
sim:body{ material = el, region = lamina.disk{ center = {0.5, 0.5}, radius = 0.2 } }
-- ".." that stays inside is fine
sim:frame{ file = "out/security/root/../dotdot_inside.png", width = 16, height = 16 }
sim:frame{ file = "out/../../../x.png", width = 16, height = 16 }
