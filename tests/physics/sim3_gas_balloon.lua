-- A gas inside a closed 3D membrane (issue 34 items 2-3): the gas-filled
-- sphere settles at sigma t = p r / 2 and agrees with the axisymmetric run
-- of the same sphere. The gas (sim:body, lamina.gas) and the membrane
-- (sim:membrane, lamina.sphere) share the 3D grid: the gas's stress enters
-- the nodal forces, the membrane's points take their velocity from the same
-- nodes, so the gas pushes on the skin and the skin holds the gas through
-- the grid, as in 2D ([F] §4.3; docs/3d.md "A gas inside a 3D membrane").
--
-- The sphere (axisym_sphere.lua's, ours): radius R = 0.5 about the origin,
-- membrane E = 1e6, nu = 0.3, t = 0.1, rho = 0.5, plane stress, laid on the
-- sphere at half the equilibrium strain (eps = p R (1 - nu) / (2 E t) =
-- 1.75e-3, small), points h / 3 apart; gas p = 1000, rho = 1, gamma = 1.4,
-- mu = 0.2, 27 points a cell; B-spline grid, MUSL, cell 0.1 (level 1; 1/15
-- at level 2, the heavy variant), dt = 5e-4 h. The gas pushes the skin out;
-- a damping load c = 600 /s on the membrane's points (sim:membrane{damping})
-- settles it in about two breathing periods (0.022 s).
--
-- The 3D gas is seeded at the centres of the sub-cells inside the ball, so
-- its volume sum V_p is not the ball's (0.5306 against 0.5236 at level 1);
-- "the same sphere" as the axisymmetric run (fill = "clipped": the exact
-- half disc) holds the same gas: rho and p are scaled by V_ball / sum V_p,
-- counted on a sim of the gas alone before the run.
--
-- Checked over the window t_end / 2 .. t_end (sampled every 5e-4):
--  1. the time mean of the points' mean tension (t11 + t22) / 2 (N/m: sigma
--     t) against the time mean of p r / 2, p the gas's pressure over the
--     space the membrane encloses, (gamma - 1) sum m e / V (the sum the
--     internal forces use; V = sum A n . x / 3 over the points, the
--     divergence theorem with their current areas and normals), r the radius
--     of the sphere of that volume: within 2 %; t11 and t22 each too. p and
--     V are gas:pressure(mem) and mem:enclosed_volume(), checked against the
--     sums made here at the start (1e-9: the API sums about the points'
--     mean, this about the centre);
--  2. the axisymmetric run (lamina.sim{axisymmetric = true}, the half
--     section, grid damping 600 /s, the meridional stress and the points'
--     hoop stress weighted by ring area, as tests/verify/lib/gas_balloon.lua
--     measures them) against the same relation, and the 3D tension against
--     both of its stresses: within 2 %;
--  3. energy: the total (kinetic, strain, the gas's internal) never above its
--     start; total + sim:energy().damped (the work of the damping load, ours:
--     sim3_membrane_step.c) within 3e-5 of the total of the start at every
--     sample, and within 1 % of the damped work at the end. The undamped run
--     (c = 0) rings by +-2.3e-5 of the total at step ends in its first 6 ms
--     (measured, 2.5e-4 sampling): the step's own error, which the damped
--     run has too before it settles;
--  4. no gas point farther than a quarter cell outside the skin (signed
--     distance along the nearest point's normal) at any 0.02 s sample,
--     counted here and by mem:escaped(gas) (the same count).
-- Measured (level 1; since MUSL moves the skin's points with the re-mapped
-- velocity, docs/3d.md): 3D +0.226 % (t11 / t22 +0.253 / +0.199 %), the
-- points' rms off p r / 2 up to 19 % in the window (printed, not held: single
-- points carry the gas's noise, the mean does not); axisymmetric meridional
-- -0.107 %, hoop +0.014 %; 3D against them +0.248 / +0.127 %; energy:
-- total never above the start, |total + damped - start| 1.07e-5 of the total
-- at worst (in the first ms), 0.42 % of the damped work at the end (0.24 %
-- before that change); no gas outside the skin (the outermost 0.002 cells
-- inside). Level 2 (the heavy variant, 67 s CPU; measured before that change,
-- passes after it): 3D +0.70 %;
-- axisymmetric -0.07 / +0.01 %; 3D against them +0.71 / +0.63 %; energy
-- 3.0e-6 of the total; no gas outside.
local level = lamina.param("level", 1)
assert(level == 1 or level == 2, "level must be 1 or 2")
local p0, rho0, R, t, E, nu = 1000, 1, 0.5, 0.1, 1e6, 0.3
local h = level == 1 and 0.1 or 1 / 15
local dt = 5e-4 * h
local c = 600
local t_end = level == 1 and 0.08 or 0.12
local ppc = 27
local eq = p0 * R / (2 * t) * (1 - nu) / E
local Vball = 4 / 3 * math.pi * R ^ 3
local skin = lamina.membrane{ rho = 0.5, E = E, nu = nu, thickness = t, law = "plane_stress" }

-- the 3D sim; ball = the gas's region
local function sim3d()
  return lamina.sim{ dim = 3, domain = {-1, -1, -1, 1, 1, 1}, cell = h, dt = dt,
                     basis = "bspline2", scheme = "musl" }
end
local ball = lamina.ball{ center = {0, 0, 0}, radius = R }

-- the gas's volume as seeded, from a sim of the gas alone
local probe = sim3d()
local np = #probe:body{ material = lamina.gas{ rho = rho0, p = p0, gamma = 1.4 }, ppc = ppc,
                        region = ball }
local scale = Vball / (np * h ^ 3 / ppc)

local sim = sim3d()
local air = lamina.gas{ rho = rho0 * scale, p = p0 * scale, gamma = 1.4, mu = 0.2 }
local gas = sim:body{ material = air, ppc = ppc, name = "gas", region = ball }
local mem = sim:membrane{ material = skin, spacing = h / 3, initial_strain = eq / 2, damping = c,
                          surface = lamina.sphere{ center = {0, 0, 0}, radius = R } }
assert(#gas == np, "the probe counts the same points")

-- p over the enclosed volume, the volume's radius, the points' tensions
local checked = false
local function state()
  local m = mem:particles()
  local V, T, T1, T2 = 0, 0, 0, 0
  for i = 1, m.n do
    V = V + m.area[i] * (m.x[i] * m.nx[i] + m.y[i] * m.ny[i] + m.z[i] * m.nz[i]) / 3
    T, T1, T2 = T + m.tension[i], T1 + m.t11[i], T2 + m.t22[i]
  end
  -- the API's (l_membrane3_gas.c): the same sums, V about the points' mean
  local Va, pa = mem:enclosed_volume(), gas:pressure(mem)
  if not checked then
    local g = gas:particles()
    local me = 0
    for i = 1, g.n do me = me + g.mass[i] * g.e[i] end
    assert(math.abs(Va / V - 1) < 1e-9 and math.abs(pa / (0.4 * me / V) - 1) < 1e-9,
           string.format("the API's volume and pressure: %.12g, %.12g against %.12g, %.12g", Va, pa, V,
                         0.4 * me / V))
    checked = true
  end
  return pa, (3 * Va / (4 * math.pi)) ^ (1 / 3), T / m.n, T1 / m.n, T2 / m.n, Va, m
end

local p, r, _, _, _, V = state()
print(string.format("level %d: %d gas points (volume %.5f, ball %.5f: rho and p x %.6f), %d membrane "
                    .. "points; start p = %.4f over V = %.6f", level, np, np * h ^ 3 / ppc, Vball,
                    scale, #mem, p, V))
assert(math.abs(p / p0 - 1) < 1e-3 and math.abs(V / Vball - 1) < 1e-9, "the start's pressure and volume")

-- gas points outside the skin: signed distance along the nearest membrane
-- point's normal (points bucketed by cell; only gas beyond R - h is looked at)
local function outside(m)
  local buckets = {}
  local function key(i, j, k) return (i * 1024 + j) * 1024 + k end
  local function cell(x) return math.floor((x + 1) / h) end
  for i = 1, m.n do
    local kk = key(cell(m.x[i]), cell(m.y[i]), cell(m.z[i]))
    local b = buckets[kk]
    if not b then b = {}; buckets[kk] = b end
    b[#b + 1] = i
  end
  local g = gas:particles()
  local beyond, deepest = 0, -math.huge
  for j = 1, g.n do
    local x, y, z = g.x[j], g.y[j], g.z[j]
    if x * x + y * y + z * z > (R - h) ^ 2 then
      local best, bi = math.huge, nil
      local ci, cj, ck = cell(x), cell(y), cell(z)
      for a = -1, 1 do for b = -1, 1 do for d = -1, 1 do
        for _, i in ipairs(buckets[key(ci + a, cj + b, ck + d)] or {}) do
          local d2 = (x - m.x[i]) ^ 2 + (y - m.y[i]) ^ 2 + (z - m.z[i]) ^ 2
          if d2 < best then best, bi = d2, i end
        end
      end end end
      assert(bi, "a gas point more than a cell from every membrane point at radius "
                 .. math.sqrt(x * x + y * y + z * z))
      local s = (x - m.x[bi]) * m.nx[bi] + (y - m.y[bi]) * m.ny[bi] + (z - m.z[bi]) * m.nz[bi]
      deepest = math.max(deepest, s)
      if s > h / 4 then beyond = beyond + 1 end
    end
  end
  return beyond, deepest
end

local e0 = sim:energy()
local sT, sT1, sT2, sX, n = 0, 0, 0, 0, 0
local grow, unbalanced, escaped, deepest = -math.huge, 0, 0, -math.huge
local rms = 0
sim:every(5e-4, function(s)
  local pp, rr, T, T1, T2, _, m = state()
  local e = sim:energy()
  grow = math.max(grow, e.total - e0.total)
  unbalanced = math.max(unbalanced, math.abs(e.total + e.damped - e0.total))
  if s.t >= t_end / 2 - 1e-9 then
    sT, sT1, sT2, sX, n = sT + T, sT1 + T1, sT2 + T2, sX + pp * rr / 2, n + 1
    local q = 0
    for i = 1, m.n do q = q + (m.tension[i] / (pp * rr / 2) - 1) ^ 2 end
    rms = math.max(rms, math.sqrt(q / m.n))
  end
  if math.abs(s.t / 0.02 - math.floor(s.t / 0.02 + 0.5)) < 1e-6 then
    local b, d = outside(m)
    local ba, da, ga = mem:escaped(gas)   -- the API's, the same count
    assert(ba == b and (d > 0 or (da == 0 and ga == 0)) and (d <= 0 or math.abs(da - d) < 1e-12),
           string.format("mem:escaped(gas) = %d, %g, %d against %d, %g here", ba, da, ga, b, d))
    escaped, deepest = math.max(escaped, b), math.max(deepest, d)
    print(string.format("  t = %.3f: p = %.4f, r = %.6f, sigma t / (p r / 2) - 1 = %+.4f %%, gas beyond "
                        .. "h/4 %d (outermost %+.3f cells)", s.t, pp, rr, 100 * (T / (pp * rr / 2) - 1),
                        b, d / h))
  end
end)
sim:run{ t_end = t_end }
local damped = sim:energy().damped
local final = math.abs(sim:energy().total + damped - e0.total)
local err3, err1, err2 = sT / sX - 1, sT1 / sX - 1, sT2 / sX - 1
print(string.format("3D: time mean sigma t / (p r / 2) - 1 = %+.3f %% (t11 %+.3f %%, t22 %+.3f %%), "
                    .. "points' rms at worst %.2f %%; sigma t = %.4f N/m", 100 * err3, 100 * err1,
                    100 * err2, 100 * rms, sT / n))
print(string.format("energy: total - start at most %+.3g J; |total + damped - start| at most %.3g J "
                    .. "(%.3g of the total), at the end %.3g J (%.3g of the damped work %.4g J); gas "
                    .. "beyond a quarter cell outside: %d, outermost %+.3f cells", grow, unbalanced,
                    unbalanced / e0.total, final, final / damped, damped, escaped, deepest / h))

-- the axisymmetric run of the same sphere (the half section in (r, z))
local axi = lamina.sim{ domain = {0, -1, 1, 1}, cell = h, dt = dt, axisymmetric = true,
                        basis = "bspline2", damping = c, mass = "lumped",
                        boundary = { left = "symmetry", bottom = "fixed", right = "fixed", top = "fixed" } }
local gas2 = axi:body{ material = lamina.gas{ rho = rho0, p = p0, gamma = 1.4, mu = 0.2 }, ppc = 16,
                       name = "gas", fill = "clipped", region = lamina.disk{ center = {0, 0}, radius = R } }
local count = math.ceil(math.pi * R / (h / 3) - 1e-9) + 1
local mem2 = axi:membrane{ material = skin, count = count, name = "membrane", orient = {0, 0},
                           initial_strain = eq / 2,
                           curve = lamina.arc{ center = {0, 0}, radius = R, from = 90, to = -90 } }
local aM, aH, aX, an = 0, 0, 0, 0
axi:every(5e-4, function(s)
  if s.t < t_end / 2 - 1e-9 then return end
  local pp = gas2:pressure(mem2, {0, 0})
  local rr = math.sqrt(2 * mem2:enclosed_area({0, 0}) / math.pi)   -- the half disc's radius
  local q = mem2:particles()
  local sh, w = 0, 0
  for i = 1, q.n do
    local a = q.mass[i] / q.rho[i]
    sh, w = sh + a * q.szz[i], w + a
  end
  aM, aH, aX, an = aM + mem2:hoop_stress() * t, aH + sh / w * t, aX + pp * rr / 2, an + 1
end)
axi:run{ t_end = t_end }
local am, ah = aM / aX - 1, aH / aX - 1
local dm, dh = (sT / n) / (aM / an) - 1, (sT / n) / (aH / an) - 1
print(string.format("axisymmetric: meridional %+.3f %%, hoop %+.3f %% off p r / 2 (%.4f, %.4f N/m); "
                    .. "3D against them %+.3f / %+.3f %%", 100 * am, 100 * ah, aM / an, aH / an,
                    100 * dm, 100 * dh))

assert(math.abs(err3) < 0.02 and math.abs(err1) < 0.02 and math.abs(err2) < 0.02,
       string.format("3D sigma t off p r / 2 by %.3f %% (limit 2 %%)", 100 * err3))
assert(math.abs(am) < 0.02 and math.abs(ah) < 0.02, "the axisymmetric run off p r / 2")
assert(math.abs(dm) < 0.02 and math.abs(dh) < 0.02,
       string.format("3D against the axisymmetric run: %.3f / %.3f %% (limit 2 %%)", 100 * dm, 100 * dh))
assert(grow <= 1e-9 * e0.total, string.format("the total energy grew by %.3g J", grow))
assert(damped > 0 and unbalanced < 3e-5 * e0.total,
       string.format("total + damped off the start by %.3g J (%.3g of the total)", unbalanced,
                     unbalanced / e0.total))
assert(final < 0.01 * damped,
       string.format("total + damped off the start at the end by %.3g J, the damped work %.3g J", final, damped))
assert(escaped == 0, escaped .. " gas points more than a quarter cell outside the skin")
