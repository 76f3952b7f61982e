-- lamina.sim{mass = "membrane"} (issue 30 item 2, src/mpm/mass_corrected.c):
-- the consistent-mass correction of the membranes' points only, every other
-- point lumped. Checked here, each against an independent run:
--  1. a scene without a membrane (a gas and a solid disk) steps to the bit
--     as on the lumped mass (sim:hash() equal after 200 steps);
--  2. a string alone on fixed walls (every point a membrane's) steps as
--     under mass = "corrected" (the same M_C, summed as a difference
--     instead: positions equal to 1e-9 of the amplitude after 2000 steps);
--  3. a gas-filled membrane flying free (no walls reached, no gravity)
--     keeps its total momentum (the correction sums to zero over the
--     nodes: M_C' 1 = M_L 1) to 1e-12 of the largest single point's
--     momentum times the point count, over 300 steps.
local function gas_and_disk(mass)
  local sim = lamina.sim{ domain = {0, 0, 1, 1}, cell = 0.05, dt = 5e-5, mass = mass, gravity = {0, -9.81} }
  sim:body{ material = lamina.gas{ rho = 1, p = 100, gamma = 1.4 }, ppc = 4,
            region = lamina.rect{ min = {0, 0}, max = {1, 0.5} } }
  sim:body{ material = lamina.elastic{ rho = 500, E = 1e5, nu = 0.3 }, ppc = 4, velocity = {0, -1},
            region = lamina.disk{ center = {0.5, 0.75}, radius = 0.1 } }
  sim:step(200)
  return sim:hash()
end
local h1, h2 = gas_and_disk("lumped"), gas_and_disk("membrane")
print("1. no membrane: hash lumped " .. h1 .. ", membrane " .. h2)
assert(h1 == h2, "mass = \"membrane\" changed a scene without membranes")

local function string_on_walls(mass)
  local h = 1 / 16
  local sim = lamina.sim{ domain = {0, 0, 1, 0.5}, cell = h, dt = 0.4 * h / (math.sqrt(5e4 / 100) / 0.75),
                          boundary = "fixed", mass = mass }
  local wire = lamina.membrane{ rho = 100, E = 5e4, nu = 0, thickness = 0.01, law = "uniaxial" }
  local s = sim:membrane{ material = wire, count = 33, initial_strain = 0.01,
                          curve = function(u) return u, 0.25 + 2e-4 * math.sin(3 * math.pi * u) end }
  sim:step(2000)
  return s:particles()
end
local a, b = string_on_walls("corrected"), string_on_walls("membrane")
local d = 0
for i = 1, #a.x do d = math.max(d, math.abs(a.x[i] - b.x[i]), math.abs(a.y[i] - b.y[i])) end
print(string.format("2. string alone: largest difference from mass = \"corrected\" %.3g (amplitude 2e-4)", d))
assert(d <= 1e-9 * 2e-4, "mass = \"membrane\" differs from \"corrected\" on a membrane alone by " .. d)

local sim = lamina.sim{ domain = {0, 0, 2, 2}, cell = 0.05, dt = 1e-5, mass = "membrane", boundary = "free" }
sim:body{ material = lamina.gas{ rho = 1, p = 200, gamma = 1.4 }, ppc = 4, fill = "clipped", velocity = {3, 1},
          region = lamina.disk{ center = {1, 1}, radius = 0.3 } }
local skin = sim:membrane{ material = lamina.membrane{ rho = 0.5, E = 1e6, nu = 0.3, thickness = 0.05 },
                           curve = lamina.arc{ center = {1, 1}, radius = 0.3, from = 0, to = 360 },
                           spacing = 0.02, velocity = {3, 1} }
local px0, py0 = sim:momentum()
sim:step(300)
local px, py = sim:momentum()
local q = skin:particles()
local scale = 0
for i = 1, #q.x do scale = math.max(scale, q.mass[i] * math.sqrt(q.vx[i] ^ 2 + q.vy[i] ^ 2)) end
scale = scale * (#q.x)
local drift = math.max(math.abs(px - px0), math.abs(py - py0))
print(string.format("3. free balloon: momentum (%.12g, %.12g) -> (%.12g, %.12g), drift %.3g of %.3g",
                    px0, py0, px, py, drift, scale))
assert(drift <= 1e-12 * scale, "momentum not kept under mass = \"membrane\": drift " .. drift)
