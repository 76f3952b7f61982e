-- A 3D frame draws the membranes' points and normals (frame3d's
-- lr_membrane3d; tests/io/frame3d_membrane.sh reads the lamina:layers
-- chunk): a sphere and a pinned sheet, drawn with normals, without, and
-- without membranes. --set out=DIR
local out = lamina.param("out", "out/frame3d_membrane")
local skin = lamina.membrane{ rho = 1000, E = 1e6, nu = 0.3, thickness = 1e-3, law = "plane_stress" }
local sim = lamina.sim{ dim = 3, domain = {0, 0, 0, 1, 1, 1}, cell = 0.05, dt = 5e-4, basis = "bspline2" }
local a = sim:membrane{ material = skin, spacing = 0.05, pressure = 100, damping = 200,
                        surface = lamina.sphere{ center = {0.5, 0.5, 0.55}, radius = 0.3 } }
local b = sim:membrane{ material = skin, spacing = 0.025, initial_strain = 0.01, pin = "edges",
                        surface = lamina.rect3{ origin = {0.1, 0.1, 0.1}, u = {0.8, 0, 0}, v = {0, 0.8, 0} } }
print(string.format("points %d %d", #a, #b))
sim:step(20)
sim:frame{ file = out .. "/normals.png" }
sim:frame{ file = out .. "/points.png", normals = false }
sim:frame{ file = out .. "/none.png", membranes = false }
