-- The session's new features in one short run, for the leak test under
-- valgrind: segment forces, pins (one driven), contact-release, a recorder,
-- VTK output, a checkpoint, a frame with phi and contact nodes, read_csv.
local out = lamina.param("out", "out/leak_features")
local sim = lamina.sim{domain = {0, 0, 1, 1}, cell = 0.1, dt = 2e-5, basis = "gimp",
                       boundary = "free"}
local skin = lamina.membrane{rho = 1000, E = 1e7, thickness = 0.01}
local sheet = sim:membrane{material = skin, count = 25, force = "segment", name = "sheet",
                           initial_strain = 0.01, normals = "isosurface", orient = {0.5, 0},
                           curve = lamina.segment{from = {0.1, 0.4}, to = {0.9, 0.4}}}
sheet:pin{points = {1}}
sheet:pin{points = {#sheet}, velocity = function(t) return 0, 0.1 * t end}
local el = lamina.elastic{rho = 500, E = 1e5, nu = 0.3}
local ball = sim:body{material = el, region = lamina.disk{center = {0.5, 0.6}, radius = 0.12},
                      velocity = {0, -1}, name = "ball"}
sim:contact{sheet, ball, law = "release"}
sim:record{file = out .. "/h.csv", every = 1e-4, values = {y = function() local _, y = ball:com(); return y end}}
sim:vtk{file = out .. "/run", every = 2e-4}
sim:checkpoint{file = out .. "/run.ckpt", every = 2e-4}
sim:run{t_end = 4e-4}
sim:frame{file = out .. "/f.png", width = 160, height = 160, phi = true, contact = true, normals = true}
local h, names, n = lamina.read_csv(out .. "/h.csv")
assert(n >= 4 and #names == 3, "read_csv")
print("leak_features: ran", sim.nstep, "steps")
