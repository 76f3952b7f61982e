-- dogbone.lua - the quarter dog-bone of the membrane expansion problem
-- ([F] §4.3, Fig 10; [T] §6.2, Fig 47; docs/physics.md V7).
--
-- The texts keep only the labels "x = 0.5", "y = 1", "Pi = 100", the 0 and
-- 90 degree directions and a 0.1 cell for scale. Our construction, in the
-- quarter x >= 0, y >= 0 (symmetry lines x = 0 and y = 0):
--   * a lobe: the superellipse |x/0.5|^3 + |(y - 0.5)/0.5|^3 = 1, so the
--     labelled extents are x = 0.5 (its widest) and y = 1 (its top);
--   * a neck: the straight x = neck (0.35) from the 0-degree axis up to
--     where it meets the lobe, so the waist at y = 0 is narrower than the
--     lobe (the full shape, mirrored, is two lobes joined by a neck);
--   * quarter gas area 0.447 (docs/physics.md: 0.44-0.47 from [F]'s total mass),
--     geometric quarter length 1.390;
--   * the membrane is slack: it carries natural_length = 2.2 of material
--     (docs/physics.md: ~2.2, the quarter circle of the final radius ~1.39-1.40)
--     pressed into 1.390, i.e. an initial (logarithmic) strain of
--     ln(1.390/2.2) = -0.459, with the one-way (wrinkle) law on ([T] Table
--     4: "wrinkle algorithm on"). Taut, it is the quarter circle of radius
--     2.2 / (pi/2) = 1.40; energy conservation then gives
--     p = 0.447 * 250 * 0.4 / (pi/4 1.40^2) = 29.0, beside [T] Table 5's
--     1.394-1.396 and 29.0.
-- Since then [T] Appendix A.4.7 (Box 9, the input deck of simulation 4)
-- has been read: assets/lua/dogbone_box9.lua builds the deck's gas (two
-- quadrilaterals, area 0.475) and membrane line, and the V7 reference page
-- scripts/paper/gas_dogbone.lua runs it. This construction stays as a
-- variant (scripts/paper/gas_dogbone_superellipse.lua) and for the tests
-- and pages written on it.
local M = { neck = 0.35, a = 0.5, b = 0.5, yc = 0.5, n = 3, natural_length = 2.2 }

-- The lobe's half-width at height y (0 outside it).
local function lobe_x(y)
  local s = math.abs(y - M.yc) / M.b
  if s >= 1 then return 0 end
  return M.a * (1 - s ^ M.n) ^ (1 / M.n)
end

-- The quarter boundary as a polyline from the 0-degree axis to the
-- 90-degree axis, dense enough for sim:membrane to place points on.
function M.polyline(samples)
  samples = samples or 2000
  local pts = {}
  -- neck: from (neck, 0) up to where the lobe is as wide as the neck
  local lo, hi = 0, M.yc
  for _ = 1, 60 do
    local mid = 0.5 * (lo + hi)
    if lobe_x(mid) < M.neck then lo = mid else hi = mid end
  end
  local y_meet = 0.5 * (lo + hi)
  pts[#pts + 1] = {M.neck, 0}
  pts[#pts + 1] = {M.neck, y_meet}
  -- lobe: the superellipse parametrised by angle, from the meeting point
  -- round its right side to the top (0, yc + b)
  local function at(t)
    local c, s = math.cos(t), math.sin(t)
    local sc = (c >= 0 and 1 or -1) * math.abs(c) ^ (2 / M.n)
    local ss = (s >= 0 and 1 or -1) * math.abs(s) ^ (2 / M.n)
    return M.a * sc, M.yc + M.b * ss
  end
  local t0 = -math.asin(((M.yc - y_meet) / M.b) ^ (M.n / 2))
  for i = 1, samples do
    local t = t0 + (math.pi / 2 - t0) * i / samples
    local x, y = at(t)
    if i == samples then x, y = 0, M.yc + M.b end
    pts[#pts + 1] = {x, y}
  end
  return pts
end

-- The region inside the quarter boundary (for seeding the gas).
function M.contains(x, y)
  if x < 0 or y < 0 then return false end
  local w = lobe_x(y)
  if y < M.yc and w < M.neck then w = M.neck end
  if y < M.yc and lobe_x(y) >= M.neck then w = lobe_x(y) end
  return x <= w and y <= M.yc + M.b
end

function M.length(pts)
  local l = 0
  for i = 2, #pts do
    l = l + math.sqrt((pts[i][1] - pts[i - 1][1])^2 + (pts[i][2] - pts[i - 1][2])^2)
  end
  return l
end

-- The membrane point counts of [T] Table 5 at cells 0.4 / 0.2 / 0.1 / 0.05.
M.counts = { [0.4] = 56, [0.2] = 100, [0.1] = 200, [0.05] = 400 }

-- The expansion problem at cell h ([F] Table II: gas rho = 1, mu = 0.2,
-- e = 250, gamma = 1.4, AV off, 64 ppc; membrane rho = 0.5, E = 1e6,
-- nu = 0.3, t = 0.1, plane stress, one-way law; quarter symmetry;
-- dt = 0.5 h / c_membrane). o: normals (default "connectivity", oriented
-- away from the origin), pic (default 0), split (gas splitting, default
-- none), threads (default 1), density (lamina.gas{density}, default
-- "continuity"), force (sim:membrane{force}, default "point"), mass
-- (lamina.sim{mass}, default the sim's), multirate (the gas's step m x dt
-- with the membrane sub-stepped, below). Returns sim, gas, membrane.
function M.setup(h, o)
  o = o or {}
  local cm = math.sqrt(1e6 / ((1 - 0.3^2) * 0.5))
  -- o.multirate = m (> 1): the gas at m x this dt, the membrane in the
  -- fewest sub-steps within its Courant limit, the impulse form, and a gas
  -- point's viscosity at most 0.25 rho h^2 / dt (docs/performance.md "The
  -- gas's step beside a membrane"); nil or 1: the plain step, as before
  local m = o.multirate and o.multirate > 1 and o.multirate or nil
  local sim = lamina.sim{ domain = {0, 0, 1.6, 1.6}, cell = h, dt = 0.5 * h / cm * (m or 1),
                          boundary = { left = "symmetry", bottom = "symmetry",
                                       right = "fixed", top = "fixed" },
                          pic = o.pic or 0, threads = o.threads,
                          basis = o.basis or "linear", mass = o.mass,
                          substeps = m and "auto", multirate = m and "impulse", viscous_limit = m and 0.25 }
  local air = lamina.gas{ rho = 1, e = 250, gamma = 1.4, mu = 0.2, split = o.split,
                          density = o.density }
  local skin = lamina.membrane{ rho = 0.5, E = 1e6, nu = 0.3, thickness = 0.1,
                                law = "plane_stress", one_way = true }
  local gas = sim:body{ material = air, ppc = 64, region = M.contains, name = "gas" }
  local pts = M.polyline()
  local mem = sim:membrane{ material = skin, name = "membrane",
                            count = o.count or M.counts[h] or math.floor(2 / (h / 10) + 0.5),
                            normals = o.normals or "connectivity", orient = {0, 0},
                            force = o.force or "point",
                            initial_strain = math.log(M.length(pts) / M.natural_length),
                            curve = lamina.polyline(pts) }
  return sim, gas, mem
end

return M
