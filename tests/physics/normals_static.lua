local nu = require("normals_util")
local angle, median, spaced = nu.angle, nu.median, nu.spaced
local function max_error(r, ex)
  local m = 0
  for k = 1, #ex do m = math.max(m, angle(r.normals[k], ex[k])) end
  return m
end

-- the shape of a result
do
  local pts = {{0.2, 0.2}, {0.5, 0.5}, {0.8, 0.8}}
  local r = lamina.normals{points = pts, box = {0, 0, 1, 1}, basis = "linear", seed = 7}
  assert(#r.normals == 3 and #r.phi == 4 and #r.nodes == 4, "a 2D linear result")
  for k = 1, 3 do
    local n = r.normals[k]
    assert(math.abs(n[1] ^ 2 + n[2] ^ 2 - 1) < 1e-14, "unit normals")
    assert(math.abs(r.phi_at(pts[k][1], pts[k][2]) - 1) < 1e-12, "phi = 1 at the points")
  end
  assert(math.abs(r.phi_at(r.random_point[1], r.random_point[2])) < 1e-12, "phi = 0 there")
  assert(r.cond > 1 and r.rank == 4 and r.unknowns == 4 and r.rows == 4)
  local q = lamina.normals{points = pts, box = {0, 0, 1, 1}, basis = "quadratic", seed = 7}
  assert(#q.phi == 9 and q.underdetermined and q.rank == 4, "9 unknowns, 4 rows")
  local r3 = lamina.normals{points = {{0.1, 0.2, 0.3}, {0.5, 0.1, 0.2}, {0.3, 0.9, 0.4}},
                            box = {0, 0, 0, 1, 1, 1}}
  assert(#r3.phi == 8 and #r3.normals[1] == 3, "a 3D linear result")
  local same = lamina.normals{points = pts, box = {0, 0, 1, 1}, seed = 7}
  assert(same.normals[2][1] == r.normals[2][1] and same.cond == r.cond, "deterministic")
end

-- N1
local function line(s, n)
  local x0, x1 = 0, 1
  if math.abs(s) > 1 then
    x0, x1 = math.min(0.5 - 0.5 / s, 0.5 + 0.5 / s), math.max(0.5 - 0.5 / s, 0.5 + 0.5 / s)
  end
  local pts, ex = {}, {}
  local l = math.sqrt(1 + s * s)
  for k = 0, n - 1 do
    local x = x0 + (k + 0.5) / n * (x1 - x0)
    pts[#pts + 1], ex[#ex + 1] = {x, 0.5 + s * (x - 0.5)}, {-s / l, 1 / l}
  end
  return pts, ex
end
local table1 = {[0.1] = 5.0e3, [0.5] = 1.7e2, [1.0] = 5.9e1, [2.0] = 3.6e2, [10.0] = 5.4e3,
                [-10.0] = 5.3e3, [-2.0] = 3.3e2, [-1.0] = 6.1e1, [-0.5] = 1.2e2, [-0.1] = 6.0e3}
local worst = 0
for s, paper in pairs(table1) do
  for _, n in ipairs({3, 4, 8}) do
    local pts, ex = line(s, n)
    local conds = {}
    for t = 1, 30 do
      local r = lamina.normals{points = pts, box = {0, 0, 1, 1}, seed = t}
      worst = math.max(worst, max_error(r, ex))
      conds[t] = r.cond
    end
    if n == 3 then
      local ratio = median(conds) / paper
      assert(ratio > 0.1 and ratio < 10, string.format("slope %g: median cond %.3g vs Table I %.3g",
        s, median(conds), paper))
    end
  end
end
print(string.format("N1: worst normal error %.2e rad", worst))
assert(worst < 1e-10, "N1: lines must be exact")

-- N2
do
  local pts, ex = {}, {}
  for k = 0, 2 do
    local x = -1 + (k + 0.5) / 3 * (1 - 0.3 / 1.1)
    local y = -0.1 - 0.3 / x
    local l = math.sqrt((y + 0.1) ^ 2 + x * x)
    pts[#pts + 1], ex[#ex + 1] = {x, y}, {(y + 0.1) / l, x / l}
  end
  local r = lamina.normals{points = pts, box = {-1, 0, 0, 1}, seed = 3}
  print(string.format("N2: bilinear curve error %.2e rad", max_error(r, ex)))
  assert(max_error(r, ex) < 1e-10, "N2: the bilinear curve must be exact")

  local function circle(n)
    local p, e = {}, {}
    for k = 0, n - 1 do
      local t = 0.5 * math.pi * k / (n - 1)
      p[#p + 1], e[#e + 1] = {0.8 * math.cos(t), 0.8 * math.sin(t)}, {math.cos(t), math.sin(t)}
    end
    return p, e
  end
  local p3 = circle(3)
  local q = lamina.normals{points = p3, box = {0, 0, 1, 1}, seed = 1}.random_point
  local paper = {[3] = 0.1211, [4] = 0.1091, [8] = 0.1177, [16] = 0.1261, [32] = 0.1308}
  local last = math.huge
  for _, n in ipairs({3, 4, 8, 16, 32}) do
    local p, e = circle(n)
    local r = lamina.normals{points = p, box = {0, 0, 1, 1}, random_point = q}
    local s2, m = 0, 0
    for k = 1, n do
      local a = angle(r.normals[k], e[k])
      s2, m = s2 + a * a, math.max(m, a)
    end
    local rms = math.sqrt(s2 / n)
    print(string.format("N2: circle, %2d points: max %.4f rad (paper %.4f), rms %.4f", n, m,
                        paper[n], rms))
    assert(m > 0.5 * paper[n] and m < 2 * paper[n], "N2: Table III max error out of order")
    assert(rms < last, "N2: the rms error must fall as points are added")
    last = rms
  end
end

-- N3, N4
local function arc(angles)
  local p, e = {}, {}
  for k, a in ipairs(angles) do
    local t = math.rad(a)
    p[k], e[k] = {0.5 + 0.3 * math.cos(t), 0.5 + 0.3 * math.sin(t)}, {math.cos(t), math.sin(t)}
  end
  return p, e
end
local function median_error(angles, basis, solver)
  local p, e = arc(angles)
  local v = {}
  for t = 1, 30 do
    v[t] = max_error(lamina.normals{points = p, box = {0, 0, 1, 1}, basis = basis,
                                    solver = solver, seed = t}, e)
  end
  return math.deg(median(v))
end
do
  local ea = median_error(spaced(180, 22.5, 5), "linear", "qr")
  local eb = median_error(spaced(225, 22.5, 5), "linear", "qr")
  print(string.format("N3: Fig 7 (a) %.1f deg (paper 6), (b) %.1f deg (paper 34)", ea, eb))
  assert(eb > 2 * ea, "N3: shared coordinates must make the linear basis much worse")

  for _, a0 in ipairs({180, 225}) do
    local p, e = arc(spaced(a0, 11.25, 8))
    for t = 1, 10 do
      local r = lamina.normals{points = p, box = {0, 0, 1, 1}, basis = "quadratic", seed = t}
      assert(max_error(r, e) < 1e-10 and r.rank == 9, "N4: 8 points must be exact")
    end
  end
  local qr = median_error(spaced(225, 22.5, 5), "quadratic", "qr")
  local ne = median_error(spaced(225, 22.5, 5), "quadratic", "normal_equations")
  print(string.format("N4: Fig 9(b) QR %.2f deg, normal equations %.2f deg (paper < 1, 19)", qr, ne))
  assert(qr < ne, "N4: QR must beat the normal equations on Fig 9(b)")
end

-- N5
do
  local cube = {0, 0, 0, 1, 1, 1}
  local l = math.sqrt(0.25 + 0.0625 + 1)
  local plane, pe = {}, {}
  for i = 0, 4 do
    for j = 0, 5 do
      local x, y = (i + 0.5) / 5, (j + 0.5) / 6
      plane[#plane + 1], pe[#pe + 1] = {x, y, 0.5 * x + 0.25 * y}, {-0.5 / l, -0.25 / l, 1 / l}
    end
  end
  local function sphere(n)
    local golden = (3 - math.sqrt(5)) * math.pi
    local p, e = {}, {}
    for k = 0, n - 1 do
      local c = (k + 0.5) / n
      local s = math.sqrt(1 - c * c)
      local ph = 0.5 * math.pi * ((k * golden) % 1.0)
      e[#e + 1] = {s * math.cos(ph), s * math.sin(ph), c}
      p[#p + 1] = {0.8 * e[#e][1], 0.8 * e[#e][2], 0.8 * e[#e][3]}
    end
    return p, e
  end
  local lin = lamina.normals{points = plane, box = cube, basis = "linear", seed = 2}
  local quad = lamina.normals{points = plane, box = cube, basis = "quadratic", seed = 2}
  local sp, se = sphere(29)
  local sq = lamina.normals{points = sp, box = cube, basis = "quadratic", seed = 2}
  local s8, e8 = sphere(8)
  local sl = lamina.normals{points = s8, box = cube, basis = "linear", seed = 1}
  print(string.format("N5: plane linear %.1e, quadratic %.1e rad; sphere quadratic %.1e rad, "
    .. "linear 8 points %.1f deg (paper 13)", max_error(lin, pe), max_error(quad, pe),
    max_error(sq, se), math.deg(max_error(sl, e8))))
  assert(#quad.phi == 27 and #lin.phi == 8, "27 and 8 unknowns")
  assert(max_error(lin, pe) < 1e-10 and max_error(quad, pe) < 1e-10, "N5: the plane must be exact")
  assert(max_error(sq, se) < 1e-10, "N5: the sphere with 29 points must be exact")
  assert(math.deg(max_error(sl, e8)) <= 13, "N5: the linear sphere beyond the paper's 13 deg")
end
