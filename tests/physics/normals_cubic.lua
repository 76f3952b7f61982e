-- The cubic method ([T] §7.3; its eqs 7.6-7.7 lost in the text, read as the
-- cubic B-spline: src/mpm/normals_variants.c), lamina.normals{method =
-- "cubic_colour"} and a membrane's normals = "cubic_colour", checked by
-- symmetries derived here (the numbers on the circle are the Fig 70/71
-- page's, scripts/paper/normals_variants_cylinder.lua, which checks the
-- engine against its own script's construction to rounding):
-- 1. A straight line y = y0 of points half a cell apart, with and without
--    a lattice of fluid points below it: the B-spline's shifts sum to one
--    (sum_k S3(r - k) = 1, so sum_k S3'(r - k) = 0), so away from the ends
--    the colour does not depend on x and its gradient is along y exactly:
--    every normal (0, +-1) to rounding; with the fluid below, (0, 1) (away
--    from the fluid). The same for a plane z = z0 in 3D, normal (0, 0, 1).
-- 2. A circle of 128 points centred on a vertex, turned by a quarter turn
--    onto itself (128 / 4 = 32): the grid is too, so point k + 32's normal
--    is point k's turned by 90 degrees, to rounding.
-- 3. A membrane runs with it, has no phi (a colour method: asking is an
--    error naming it by its number), and an unknown method is refused naming the value.
local h = 0.1

-- 1. the line, 2D
local line, fluid = {}, {}
for k = 0, 39 do line[#line + 1] = {0.025 + 0.05 * k, 0.53} end
for j = 0, 9 do
  for i = 0, 39 do
    local x, y = 0.025 + 0.05 * i, 0.025 + 0.05 * j
    if y < 0.53 then fluid[#fluid + 1] = {x, y} end
  end
end
local function worst_off(ns, pts, lo, hi, want)
  local w = 0
  for k, p in ipairs(pts) do
    if p[1] >= lo and p[1] <= hi then
      local n = ns[k]
      for a = 1, #want do w = math.max(w, math.abs(n[a] - want[a])) end
    end
  end
  return w
end
local box2 = {0, 0, 2, 1}
local vac = lamina.normals{points = line, box = box2, cells = {20, 10}, method = "cubic_colour",
                           orient = {1, 0}}.normals
-- vacuum: the sign is the colour's ridge's side (0.53 lies above the
-- vertex row at 0.5: the colour falls upward there), orient {1, 0} keeps it
local vy = vac[20][2] > 0 and 1 or -1
local wv = worst_off(vac, line, 0.6, 1.4, {0, vy})
local all = {}
for _, p in ipairs(line) do all[#all + 1] = p end
for _, p in ipairs(fluid) do all[#all + 1] = p end
local wf = worst_off(lamina.normals{points = all, box = box2, cells = {20, 10}, method = "cubic_colour",
                                    orient = {1, 0}}.normals, line, 0.6, 1.4, {0, 1})
print(string.format("line y = 0.53, 2D: largest |n - (0, +-1)| %.2e in vacuum, %.2e with fluid below", wv, wf))
assert(wv < 1e-12, "cubic normals of a straight line in vacuum: " .. wv)
assert(wf < 1e-12, "cubic normals of a straight line with fluid below: " .. wf)

-- 1. the plane, 3D: points a quarter cell apart on z = 0.53 over the
-- whole box (so that the colour is uniform in x and y about the checked
-- middle points), fluid below
local plane, all3 = {}, {}
for j = 0, 19 do
  for i = 0, 19 do plane[#plane + 1] = {0.025 + 0.05 * i, 0.025 + 0.05 * j, 0.53} end
end
for _, p in ipairs(plane) do all3[#all3 + 1] = p end
for j = 0, 19 do
  for i = 0, 19 do
    for k = 0, 9 do
      local z = 0.025 + 0.05 * k
      if z < 0.53 then all3[#all3 + 1] = {0.025 + 0.05 * i, 0.025 + 0.05 * j, z} end
    end
  end
end
local n3 = lamina.normals{points = all3, box = {0, 0, 0, 1, 1, 1}, cells = {10, 10, 10},
                          method = "cubic_colour", orient = {0.5, 0.5, 0}}.normals
local w3 = 0
for k, p in ipairs(plane) do
  local n = n3[k]
  if p[1] >= 0.4 and p[1] <= 0.6 and p[2] >= 0.4 and p[2] <= 0.6 then
    w3 = math.max(w3, math.abs(n[1]), math.abs(n[2]), math.abs(n[3] - 1))
  end
end
print(string.format("plane z = 0.53, 3D, fluid below: largest |n - (0, 0, 1)| %.2e", w3))
assert(w3 < 1e-12, "cubic normals of a plane with fluid below: " .. w3)

-- 2. the circle's quarter-turn symmetry
local n, circ = 128, {}
for k = 0, n - 1 do
  local a = 2 * math.pi * (k + 0.5) / n
  circ[#circ + 1] = {math.cos(a), math.sin(a)}
end
local cn = lamina.normals{points = circ, box = {-1.5, -1.5, 1.5, 1.5}, cells = {30, 30},
                          method = "cubic_colour", orient = {0, 0}}.normals
local wr, wo = 0, 0
for k = 1, n do
  local m = (k + 31) % n + 1                -- point k turned by 90 degrees
  local a, b = cn[k], cn[m]
  wr = math.max(wr, math.abs(b[1] + a[2]), math.abs(b[2] - a[1]))
  wo = math.max(wo, math.abs(a[1] ^ 2 + a[2] ^ 2 - 1))
  assert(a[1] * circ[k][1] + a[2] * circ[k][2] > 0, "oriented away from the centre")
end
print(string.format("circle of 128 on a vertex: quarter-turn symmetry to %.2e, unit to %.2e", wr, wo))
assert(wr < 1e-12 and wo < 1e-12, "cubic normals keep the grid's quarter-turn symmetry")

-- 3. as a membrane's per-step normals
local sim = lamina.sim{basis = "linear", domain = {-1.5, -1.5, 1.5, 1.5}, cell = h, dt = 2e-5}
local gas = sim:body{material = lamina.gas{rho = 1, p = 1000, gamma = 1.4}, ppc = 4, fill = "clipped",
                     region = lamina.disk{center = {0, 0}, radius = 1}}
local mem = sim:membrane{material = lamina.membrane{rho = 0.5, E = 1e6, nu = 0.3, thickness = 0.1},
                         curve = lamina.arc{center = {0, 0}, radius = 1, from = 0, to = 360},
                         count = 128, normals = "cubic_colour", name = "skin"}
local _ = gas
sim:step(3)
local q = mem:particles()
for i = 1, q.n do
  local nx, ny = q.nx[i], q.ny[i]
  assert(math.abs(nx * nx + ny * ny - 1) < 1e-12 and nx * q.x[i] + ny * q.y[i] > 0,
         "the membrane's cubic normals are unit and outward (closed curve)")
end
local ok, err = pcall(sim.frame, sim, {file = "out/normals_cubic/phi.png", phi = true})
assert(not ok and err:find("has no phi") and err:find("membrane 2", 1, true), "cubic: no phi: " .. tostring(err))
local okm, errm = pcall(lamina.normals, {points = circ, box = {-1.5, -1.5, 1.5, 1.5}, cells = {30, 30},
                                         method = "cubic"})
assert(not okm and errm:find("cubic_colour", 1, true), "an unknown method names the known ones: " .. errm)
print("membrane with normals = 'cubic_colour': 3 steps; phi refused: " .. err:match("phi of membrane[^\n]*"))

-- 4. colour_points = body: the colour carried on the gas's points too ([T]
-- §7.5, Fig 66(b)); only for the colour-function methods, only a body of
-- points of this simulation
local function membrane_with(normals, colour_points)
  return pcall(sim.membrane, sim, {material = lamina.membrane{rho = 0.5, E = 1e6, nu = 0.3, thickness = 0.1},
    curve = lamina.arc{center = {0, 0}, radius = 0.5, from = 0, to = 360}, count = 64,
    normals = normals, colour_points = colour_points})
end
local bad = {
  {"connectivity", gas, "colour-function normals method"},
  {"cubic_colour", mem, "not a body of points"},
  {"cubic_colour", 2, "must be a body of this simulation"},
}
for _, b in ipairs(bad) do
  local okb, eb = membrane_with(b[1], b[2])
  assert(not okb and eb:find(b[3], 1, true), "colour_points refused: " .. tostring(eb))
  print("refused: " .. eb:match("sim:membrane.*"))
end
local sim2 = lamina.sim{basis = "linear", domain = {-1.5, -1.5, 1.5, 1.5}, cell = h, dt = 2e-5}
local gas2 = sim2:body{material = lamina.gas{rho = 1, p = 1000, gamma = 1.4}, ppc = 4, fill = "clipped",
                       region = lamina.disk{center = {0, 0}, radius = 1}}
local okc, ec = pcall(sim.membrane, sim, {material = lamina.membrane{rho = 0.5, E = 1e6, nu = 0.3, thickness = 0.1},
  curve = lamina.arc{center = {0, 0}, radius = 0.5, from = 0, to = 360}, count = 64,
  normals = "cubic_colour", colour_points = gas2})
assert(not okc and ec:find("of this simulation", 1, true), "another simulation's body: " .. tostring(ec))
-- with the gas's points the cubic normals of the circle at the first step
-- are those lamina.normals gives for the same points (membrane's first)
local sim3 = lamina.sim{basis = "linear", domain = {-1.5, -1.5, 1.5, 1.5}, cell = h, dt = 1e-12}
local gas3 = sim3:body{material = lamina.gas{rho = 1, p = 1000, gamma = 1.4}, ppc = 4, fill = "clipped",
                       region = lamina.disk{center = {0, 0}, radius = 1}}
local mem3 = sim3:membrane{material = lamina.membrane{rho = 0.5, E = 1e6, nu = 0.3, thickness = 0.1},
                           curve = lamina.arc{center = {0, 0}, radius = 1, from = 0, to = 360}, count = 128,
                           normals = "cubic_colour", colour_points = gas3}
local m0, g0, pts3 = mem3:particles(), gas3:particles(), {}
for i = 1, m0.n do pts3[#pts3 + 1] = {m0.x[i], m0.y[i]} end
for i = 1, g0.n do pts3[#pts3 + 1] = {g0.x[i], g0.y[i]} end
local want = lamina.normals{points = pts3, box = {-1.5, -1.5, 1.5, 1.5}, cells = {30, 30},
                            method = "cubic_colour", orient = {0, 0}}.normals
sim3:step(1)                                 -- the normals of the step's start positions
local m1, wc = mem3:particles(), 0
for i = 1, m1.n do
  wc = math.max(wc, math.abs(m1.nx[i] - want[i][1]), math.abs(m1.ny[i] - want[i][2]))
end
print(string.format("membrane with colour_points = gas: normals as lamina.normals on the same points to %.2e", wc))
assert(wc < 1e-12, "the membrane's colour_points normals: " .. wc)
