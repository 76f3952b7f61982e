-- Used by tests/security/checkpoint_untrusted.sh and the fuzz target
-- fuzz_checkpoint (issue 31 item 3): a small scene of every kind of body -
-- an elastic disk of radius r, a pinned open membrane, gas (splitting) -
-- with a recorder and a link, checkpointed at t = 0.002.
local r = lamina.param("r", 0.12)
local ck = lamina.param("ck", "out/security/ck_scene.ck")
local sim = lamina.sim{ dt = 5e-4, domain = {0, 0, 1, 1}, cell = 0.1 }
local el = lamina.elastic{ rho = 1000, E = 1e4, nu = 0.3 }
local mm = lamina.membrane{ rho = 1000, E = 1e4, nu = 0.3, thickness = 0.01 }
local gas = lamina.gas{ rho = 1, gamma = 1.4, e = 10, split = 60 }
local disk = sim:body{ material = el, region = lamina.disk{ center = {0.3, 0.6}, radius = r } }
local sheet = sim:membrane{ material = mm, curve = lamina.segment{ from = {0.1, 0.2}, to = {0.9, 0.2} },
                            spacing = 0.05 }
sheet:pin{ points = "ends" }
sim:link{ a = {disk, 1}, b = {sheet, 5}, stiffness = 10 }
sim:body{ material = gas, region = lamina.rect{ min = {0.6, 0.5}, max = {0.9, 0.8} } }
sim:record{ file = "out/security/ck_scene.csv", energy = true }
sim:checkpoint{ file = ck, at = 0.002 }
sim:run{ t_end = 0.003 }
print("RESULT step " .. sim.nstep .. " hash " .. sim:hash())
