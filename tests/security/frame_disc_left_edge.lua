-- expect: 0
-- Found by fuzzing (tests/fuzz, fuzz_lua): particles drawn as stamped discs
-- that reach past the left edge of a small frame formed a pointer before
-- the image (undefined behaviour, UBSan pointer-overflow in stamp_disc).
-- The sanitizer pass runs this scene.
local sim = lamina.sim{ dt = 1e-3, domain = {0, 0, 1, 1}, cell = 0.05 }
local gas = lamina.gas{ rho = 1, e = 1, density = "cell" }
sim:body{ material = gas, ppc = 9, region = lamina.disk{ center = {0.5, 0.5}, radius = 17 } }
sim:frame{ file = "out/security/disc_left_edge.png", width = 32, height = 32 }
print("frame drawn")
