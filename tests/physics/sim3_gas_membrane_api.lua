-- membrane:enclosed_volume(), membrane:escaped(gas) and gas:pressure(membrane)
-- in 3D (issue 34 items 2-3; src/lua/l_membrane3_gas.c over
-- src/mpm/sim3_membrane_gas.c), each against a reference computed here, no
-- step taken:
--  1. the sphere's enclosed volume against the same sum made in Lua about
--     the points' mean (1e-12) and against 4/3 pi r^3: the Fibonacci
--     lattice's areas sum to 4 pi r^2 exactly and every point is on the
--     sphere with its normal radial, so sum A r / 3 about the centre is the
--     ball's volume to rounding; about the points' mean (what the method
--     takes, so that it does not depend on where the sphere is) it differs
--     by the mean's offset times the sampling's sum A n, measured 2.5e-11
--     (held to 1e-9);
--  2. gas:pressure(membrane) against (gamma - 1) sum m e / V made in Lua,
--     and p0 times the gas's seeded volume over the ball's;
--  3. escaped: a gas ball inside gives 0, 0, 0; a gas ball outside the
--     sphere has every point beyond a quarter cell, its deepest distance
--     the largest distance to the nearest membrane point (brute force
--     here); a shell just outside (0.1 to 0.2 cells) has every point a
--     skin-grazer and none beyond; the points of a shell inside none;
--  4. refusals: gas:pressure() without a membrane, escaped of a solid
--     body, of a body of another sim, by name.
local h, R, c = 0.1, 0.5, {0, 0, 0}
local function new() return lamina.sim{ dim = 3, domain = {-1, -1, -1, 1, 1, 1}, cell = h, dt = 1e-5 } end
local sim = new()
local skin = lamina.membrane{ rho = 0.5, E = 1e6, nu = 0.3, thickness = 0.1, law = "plane_stress" }
local air = lamina.gas{ rho = 1.2, p = 1000, gamma = 1.4 }
local mem = sim:membrane{ material = skin, spacing = h / 3, surface = lamina.sphere{ center = c, radius = R } }
local inside = sim:body{ material = air, ppc = 8, region = lamina.ball{ center = c, radius = R } }
local away = sim:body{ material = air, ppc = 8, region = lamina.ball{ center = {0.8, 0, 0}, radius = 0.15 } }
local shell = sim:body{ material = air, ppc = 27, region = function(x, y, z)
  local r = math.sqrt(x * x + y * y + z * z)
  return r > R + 0.1 * h and r < R + 0.2 * h end }
local inner = sim:body{ material = air, ppc = 27, region = function(x, y, z)
  local r = math.sqrt(x * x + y * y + z * z)
  return r > R - 0.2 * h and r < R - 0.1 * h end }
local solid = sim:body{ material = lamina.elastic{ rho = 1000, E = 1e6, nu = 0.3 }, ppc = 1,
                        region = lamina.box{ x0 = -0.95, y0 = -0.95, z0 = -0.95, x1 = -0.85, y1 = -0.85, z1 = -0.85 } }

-- 1. the volume
local m = mem:particles()
local V = mem:enclosed_volume()
local cx, cy, cz = 0, 0, 0
for i = 1, m.n do cx, cy, cz = cx + m.x[i] / m.n, cy + m.y[i] / m.n, cz + m.z[i] / m.n end
local Vl, Vo, An = 0, 0, {0, 0, 0}
for i = 1, m.n do
  Vl = Vl + m.area[i] * ((m.x[i] - cx) * m.nx[i] + (m.y[i] - cy) * m.ny[i] + (m.z[i] - cz) * m.nz[i]) / 3
  Vo = Vo + m.area[i] * (m.x[i] * m.nx[i] + m.y[i] * m.ny[i] + m.z[i] * m.nz[i]) / 3
  An[1], An[2], An[3] = An[1] + m.area[i] * m.nx[i], An[2] + m.area[i] * m.ny[i], An[3] + m.area[i] * m.nz[i]
end
local Vb = 4 / 3 * math.pi * R ^ 3
print(string.format("volume %.15g, Lua's sum about the points' mean %.15g (%.3g), about the origin %.15g, "
                    .. "the ball %.15g (%.3g); |sum A n| = %.3g m^2 (the sampling's closure), mean %.3g m from the centre",
                    V, Vl, V / Vl - 1, Vo, Vb, V / Vb - 1, math.sqrt(An[1]^2 + An[2]^2 + An[3]^2),
                    math.sqrt(cx * cx + cy * cy + cz * cz)))
-- about the points' mean (translation-invariant); the sampled sphere is
-- closed only to its quadrature (sum A n not exactly 0), so the origin's sum
-- differs by c . sum A n / 3: measured 2.5e-11 of the volume
assert(math.abs(V / Vl - 1) < 1e-12, "the enclosed volume: the sum about the points' mean")
assert(math.abs(V / Vb - 1) < 1e-9 and math.abs(Vo / Vb - 1) < 1e-12, "the enclosed volume: the ball's")

-- 2. the pressure over it
local g = inside:particles()
local me = 0
for i = 1, g.n do me = me + g.mass[i] * g.e[i] end
local p = inside:pressure(mem)
print(string.format("pressure %.12g against (gamma - 1) sum m e / V = %.12g; p0 x seeded / ball = %.12g",
                    p, 0.4 * me / V, 1000 * #inside * h ^ 3 / 8 / V))
assert(math.abs(p / (0.4 * me / V) - 1) < 1e-12, "gas:pressure(membrane)")
assert(math.abs(p / (1000 * #inside * h ^ 3 / 8 / V) - 1) < 1e-12, "p0 over the seeded volume")

-- 3. escaped
local function nearest(x, y, z)
  local best = math.huge
  for i = 1, m.n do best = math.min(best, (x - m.x[i]) ^ 2 + (y - m.y[i]) ^ 2 + (z - m.z[i]) ^ 2) end
  return math.sqrt(best)
end
local b, d, gz = mem:escaped(inside)
print("inside:", b, d, gz)
assert(b == 0 and d == 0 and gz == 0, "a gas inside is not outside")
b, d, gz = mem:escaped(inner)
print("shell inside:", b, d, gz, #inner)
assert(#inner > 500 and b == 0 and d == 0 and gz == 0, "a shell inside is not outside")
local a = away:particles()
local far = 0
for i = 1, a.n do far = math.max(far, nearest(a.x[i], a.y[i], a.z[i])) end
b, d, gz = mem:escaped(away)
print(string.format("away: %d beyond of %d, deepest %.15g (brute force %.15g), grazing %d", b, #away, d, far, gz))
assert(b == #away and gz == 0 and math.abs(d - far) < 1e-12, "a gas outside")
b, d, gz = mem:escaped(shell)
print(string.format("shell outside: %d beyond, deepest %.4f cells, %d grazing of %d", b, d / h, gz, #shell))
assert(#shell > 500 and b == 0 and gz == #shell and d > 0.1 * h * 0.9 and d <= 0.2 * h, "a shell of skin-grazers")

-- 4. refusals
local function refused(f, what)
  local ok, err = pcall(f)
  assert(not ok and tostring(err):find(what, 1, true), "expected '" .. what .. "', got: " .. tostring(err))
end
refused(function() return inside:pressure() end, "gas:pressure: in 3D give the membrane")
refused(function() return mem:escaped(solid) end, "is not a gas body")
local other = new()
local og = other:body{ material = air, ppc = 1, region = lamina.ball{ center = c, radius = 0.2 } }
refused(function() return mem:escaped(og) end, "different sims")
refused(function() return mem:escaped(mem) end, "must be a gas body")
print("refusals named")
