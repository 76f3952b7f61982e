-- body:pin in 3D (issue 34 item 1; l_pin3.c, sim3_pin.c): a pin holds the
-- grid nodes its points touch at its velocity, as a fixed wall holds its
-- nodes (the form the 2D pins take for a pinned region, docs/api.md).
-- Checks, all with numbers:
--  1. a block pinned "all" at rest under gravity does not move at all (its
--     positions equal as seeded, bit for bit) and the pin's reaction is the
--     block's weight: fz = M g (the internal forces sum to zero over the
--     nodes, sum_i G_ip = 0), to rounding;
--  2. a block pinned "all" and driven by velocity = function(t) at
--     (0.1, -0.05, 0.2) translates with it: the centre of mass at
--     x0 + v t to rounding, and the stress stays zero (a rigid motion);
--  3. a cantilever (trilinear) clamped by a pin on its first layer of
--     cells against the same bar clamped by a fixed face at the layer's
--     end: the pinned layer holds the node plane the wall is, and nothing
--     else differs, so the free particles' paths agree to rounding under
--     gravity (300 steps of 5e-4 s: a soft bar, E = 2e5, whose free part's
--     centre of mass falls by centimetres).
-- Measured: 1. displacement 0 exactly, fz / (M g) - 1 = -2e-14;
-- 2. path 7.8e-15 m, |sigma| 2.6e-11 Pa; 3. 1.1e-16 m.
local rock = lamina.elastic{ rho = 1000, E = 1e6, nu = 0.3 }

-- 1. held at rest
do
  local sim = lamina.sim{ dim = 3, domain = {0, 0, 0, 1, 1, 1}, cell = 0.1, dt = 1e-3,
                          gravity = {0, 0, -9.81} }
  local b = sim:body{ material = rock, region = lamina.box{ min = {0.3, 0.3, 0.4}, max = {0.6, 0.5, 0.6} } }
  local pin = b:pin{ points = "all" }
  assert(#pin == #b, "the pin holds " .. #pin .. " of " .. #b .. " points")
  local p0 = b:particles()
  sim:step(100)
  local p1 = b:particles()
  local moved = 0
  for i = 1, p0.n do
    moved = math.max(moved, math.abs(p1.x[i] - p0.x[i]), math.abs(p1.y[i] - p0.y[i]),
                     math.abs(p1.z[i] - p0.z[i]))
  end
  local fx, fy, fz = pin:reaction()
  local W = b:mass() * 9.81
  print(string.format("held at rest: moved %.3g m; reaction (%.3g, %.3g, %.10g) N, weight %.10g N "
    .. "(%.2g)", moved, fx, fy, fz, W, fz / W - 1))
  assert(moved == 0, "a point held at rest moved by " .. moved)
  assert(math.abs(fz / W - 1) <= 1e-12 and math.abs(fx) <= 1e-12 * W and math.abs(fy) <= 1e-12 * W,
         "the reaction is not the weight: " .. fx .. ", " .. fy .. ", " .. fz .. " against " .. W)
end

-- 2. driven
do
  local v = {0.1, -0.05, 0.2}
  local sim = lamina.sim{ dim = 3, domain = {0, 0, 0, 1, 1, 1}, cell = 0.1, dt = 1e-3,
                          gravity = {0, 0, -9.81} }
  local b = sim:body{ material = rock, region = lamina.box{ min = {0.3, 0.3, 0.4}, max = {0.6, 0.5, 0.6} } }
  b:pin{ points = "all", velocity = function(t) return v[1], v[2], v[3] end }
  local c0 = {b:com()}
  sim:step(300)
  local c = {b:com()}
  local off = 0
  for a = 1, 3 do off = math.max(off, math.abs(c[a] - (c0[a] + v[a] * sim.t))) end
  local p = b:particles()
  local smax = 0
  for _, k in ipairs{"sxx", "syy", "szz", "syz", "sxz", "sxy"} do
    for i = 1, p.n do smax = math.max(smax, math.abs(p[k][i])) end
  end
  print(string.format("driven: path off by %.3g m at t = %.3f, |sigma| <= %.3g Pa", off, sim.t, smax))
  assert(off <= 1e-12, "the driven block is off its path by " .. off)
  assert(smax <= 1e-6, "a rigidly driven block has stress " .. smax)
end

-- 3. a pinned clamp against a wall
do
  local h = 0.05
  local function cantilever(x0, pinned)
    local sim = lamina.sim{ dim = 3, basis = "linear", domain = {x0, 0, 0, 1, 0.3, 0.4}, cell = h,
                            dt = 5e-4, gravity = {0, 0, -9.81},
                            boundary = { x0 = pinned and "free" or "fixed", x1 = "free",
                                         y0 = "free", y1 = "free", z0 = "free", z1 = "free" } }
    local bar = sim:body{ material = lamina.elastic{ rho = 1000, E = 2e5, nu = 0.3 },
                          region = lamina.box{ min = {0.1, 0.1, 0.15}, max = {0.8, 0.2, 0.25} } }
    if pinned then bar:pin{ points = function(x) return x < 0.15 end } end
    return sim, bar
  end
  local sa, ba = cantilever(0, true)
  local sb, bb = cantilever(0.15, false)
  sa:step(300)
  sb:step(300)
  local pa, pb = ba:particles(), bb:particles()
  local j, diff = 0, 0
  -- the free points of the pinned run are those right of the clamp, in
  -- the same order as the wall run's (seeded x fastest, then y, z)
  local initial = {}
  do
    local s0, b0 = cantilever(0, true)
    local q = b0:particles()
    for i = 1, q.n do initial[i] = q.x[i] end
  end
  for i = 1, pa.n do
    if initial[i] > 0.15 then
      j = j + 1
      diff = math.max(diff, math.abs(pa.x[i] - pb.x[j]), math.abs(pa.y[i] - pb.y[j]),
                      math.abs(pa.z[i] - pb.z[j]))
    end
  end
  assert(j == pb.n, "free points: " .. j .. " against the wall run's " .. pb.n)
  local _, _, zc = bb:com()
  local sag = 0.2 - zc   -- the free part's centre of mass, seeded at z = 0.2
  print(string.format("clamp: %d free points, paths differ by %.3g m from the wall-clamped bar's "
    .. "(its centre of mass %.1f mm lower at t = %.2f)", j, diff, 1000 * sag, sb.t))
  assert(diff <= 1e-12, "the pinned clamp and the wall differ by " .. diff)
  assert(sag > 0.01, "the cantilever did not sag: " .. sag)
end
