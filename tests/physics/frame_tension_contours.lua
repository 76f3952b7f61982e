-- sim:frame's membrane stress and pressure contours ([T] Fig 56; docs/api.md
-- "sim:frame"): colour = "membrane_stress" (t . sigma . t of each membrane
-- point) and "tension" (that times the thickness, force per length) draw
-- before the first step (the tangents come from a prepare) and after;
-- contours = "pressure" with colour by body owns the colour bar, takes a
-- fixed range, and still refuses nothing a colour bar by body would need.
-- A failure is a Lua error (status 2).
local out = lamina.param("out", "out/frame_tension_contours")
local sim = lamina.sim{ domain = {0, 0, 1, 1}, cell = 0.1, dt = 1e-5, basis = "linear",
                        boundary = { left = "symmetry", bottom = "symmetry" } }
local skin = lamina.membrane{ rho = 1, E = 1e4, nu = 0, thickness = 0.01, one_way = true }
local gas = sim:body{ material = lamina.gas{ rho = 1, p = 10 }, ppc = 4, name = "gas",
                      region = lamina.disk{ center = {0, 0}, radius = 0.5 } }
local mem = sim:membrane{ material = skin, count = 40, force = "point", name = "skin",
                          initial_strain = 0.01,
                          curve = lamina.arc{ center = {0, 0}, radius = 0.55, from = 0, to = 90 } }
sim:frame{ file = out .. "/tension_t0.png", width = 200, height = 160, colour = "tension",
           particles = "membranes" }
sim:run{ t_end = 1e-3 }
-- the membrane points' own sigma_t (as the frame computes it) is positive: stretched
local q = mem:particles()
for i = 1, q.n do
  local tx, ty = -q.ny[i], q.nx[i]
  local st = tx * tx * q.sxx[i] + 2 * tx * ty * q.sxy[i] + ty * ty * q.syy[i]
  assert(st > 0, string.format("point %d: sigma_t = %g, expected tension", i, st))
end
sim:frame{ file = out .. "/stress.png", width = 200, height = 160, colour = "membrane_stress",
           particles = "membranes", range = {0, 200} }
sim:frame{ file = out .. "/tension.png", width = 200, height = 160, colour = "tension",
           particles = "membranes", range = {0, 2} }
sim:frame{ file = out .. "/contours.png", width = 240, height = 160, contours = "pressure",
           particles = "membranes", range = {0, 20} }
sim:frame{ file = out .. "/contours_bar.png", width = 240, height = 160, contours = "pressure",
           colourbar = true }
sim:frame{ file = out .. "/contours_nobar.png", width = 240, height = 160, contours = "pressure",
           colourbar = false }
sim:frame{ file = out .. "/contours_speed.png", width = 240, height = 160, contours = "pressure",
           colour = "speed" }
local ok, err = pcall(sim.frame, sim, { file = out .. "/x.png", colourbar = true })
assert(not ok and tostring(err):find("'colourbar' needs colour = a field"), err)
print("frame_tension_contours: ok")
