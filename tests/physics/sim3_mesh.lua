-- lamina.mesh (issue 34 items 1 and 2; src/lua/l_mesh3.c over src/mpm/mesh3*.c):
-- a triangle mesh from a file as a 3D region and as a membrane surface.
-- Assets beside this script (meshes/): cube.stl, the unit cube in ASCII STL
-- (12 triangles); icosphere3.obj, the unit icosahedron cut three times with
-- its vertices on the sphere (642 vertices, 1280 triangles). Checks:
--  1. the cube scaled to 0.4 at (0.3, 0.3, 0.3) seeds exactly lamina.box's
--     particles (no sub-cell centre lies on a face: the bound is 0), the
--     same mass; its volume and area are the box's;
--  2. the icosphere scaled to R = 0.29 at (0.51, 0.49, 0.503) seeds exactly
--     the points that an independent test computed here says are inside the
--     polyhedron (every facet's half-space: it is convex), and differs from
--     lamina.ball{R} by at most the points of the shell between the facets'
--     nearest plane r_in and R (the discretisation's bound, counted here);
--  3. the icosphere as a membrane surface (r0 = 0.3, the balloon of
--     physics.sim3_membrane: cell 0.05, B-spline, spacing h/3, p = 100 Pa,
--     damping 200, 300 steps): the triangles cut to the spacing (k = 3, the
--     point count nv + ne (k - 1) + nt (k - 1)(k - 2) / 2), the areas summing
--     to the mesh's, normals out; settled, the mean tension within 1 % of
--     p r / 2 (r the points' mean radius), the check the lamina.sphere
--     membrane passes.
--  4. the cube in binary STL (cube_binary.stl) is the ASCII one: the same
--     vertices, triangles and particles;
--  5. an open mesh (square.obj, two triangles) as a pre-tensioned sheet
--     (initial strain 1 %, side 0.5 at z = 0.11, cell 1/16, B-spline, dt
--     1e-3), pinned at its edges by a function (spacing 0.045) and by
--     pin = "edges" (its rim: spacing 0.03), spacing 0.045 and 0.03 (the
--     diagonal cut into k = 16 and 24: points every h/2 and h/3 along the
--     sides, on the grid's symmetry as the rect3 sheet of
--     physics.sim3_membrane): every free point's tension stays T0 = E t e0 /
--     (1 - nu) to rounding for 1 s, nothing moves, the normal is the file's
--     winding's (+z).
-- Measured (this run): 1. 4096 = 4096, the same mass; 2. 6493 points, the
-- half-space count 6493, lamina.ball 6541, 85 in the shell (r_in = 0.288687;
-- volume 0.86 % under the ball's); 3. k = 3, 5762 points, the areas' sum
-- equal to the mesh's to rounding, mean T / (p r / 2) - 1 = -4.32e-4, every
-- point within 3.23 % (the Fibonacci sphere's: -8.5e-6 and 3.3 %); 4. 4096
-- and 4096; 5. 289 and 625 points, tension within 4.4e-15 and 4.1e-15 of T0,
-- speed <= 1.4e-15 m/s.
local here = "meshes/"
local rock = lamina.elastic{ rho = 1000, E = 1e6, nu = 0.3 }

-- 1. the cube against lamina.box
do
  local sim = lamina.sim{ dim = 3, domain = {0, 0, 0, 1, 1, 1}, cell = 0.05, dt = 1e-4 }
  local cube = lamina.mesh{ file = here .. "cube.stl", scale = 0.4, translate = {0.3, 0.3, 0.3} }
  assert(cube.closed and cube.vertices == 8 and cube.triangles == 12, tostring(cube))
  assert(math.abs(cube.volume - 0.064) < 1e-15 and math.abs(cube.area - 0.96) < 1e-15,
         "volume " .. cube.volume .. ", area " .. cube.area)
  local a = sim:body{ material = rock, region = cube }
  local b = sim:body{ material = rock, region = lamina.box{ x0 = 0.3, y0 = 0.3, z0 = 0.3, x1 = 0.7, y1 = 0.7, z1 = 0.7 } }
  print(string.format("cube.stl: %d particles, lamina.box %d; mass %.17g and %.17g", #a, #b, a:mass(), b:mass()))
  assert(#a == #b and #a == 16 * 16 * 16, "the cube seeds the box's particles")
  assert(a:mass() == b:mass(), "and their mass")
  assert(cube:contains(0.5, 0.5, 0.5) and not cube:contains(0.75, 0.5, 0.5), "contains")
end

-- 2. the icosphere against an independent half-space test and lamina.ball
do
  local R, c = 0.29, {0.51, 0.49, 0.503}
  local sim = lamina.sim{ dim = 3, domain = {0, 0, 0, 1, 1, 1}, cell = 0.05, dt = 1e-4 }
  local ico = lamina.mesh{ file = here .. "icosphere3.obj", scale = R, translate = c }
  assert(ico.closed and ico.vertices == 642 and ico.triangles == 1280, tostring(ico))
  -- the facets' planes: unit normal n (out) and offset d = n . a
  local planes, rin = {}, math.huge
  for t = 1, ico.triangles do
    local i, j, k = ico:triangle(t)
    local ax, ay, az = ico:vertex(i)
    local bx, by, bz = ico:vertex(j)
    local cx, cy, cz = ico:vertex(k)
    local ux, uy, uz, vx, vy, vz = bx - ax, by - ay, bz - az, cx - ax, cy - ay, cz - az
    local nx, ny, nz = uy * vz - uz * vy, uz * vx - ux * vz, ux * vy - uy * vx
    local l = math.sqrt(nx * nx + ny * ny + nz * nz)
    nx, ny, nz = nx / l, ny / l, nz / l
    local d = nx * (ax - c[1]) + ny * (ay - c[2]) + nz * (az - c[3])
    assert(d > 0, "facet " .. t .. " faces out")
    planes[t] = {nx, ny, nz, d}
    rin = math.min(rin, d)
  end
  -- the sub-cell centres of ppc = 8 (2 a cell each way: 0.0125 + 0.025 i)
  local inside, ball, shell = 0, 0, 0
  for i = 0, 39 do
    for j = 0, 39 do
      for k = 0, 39 do
        local x, y, z = 0.0125 + 0.025 * i - c[1], 0.0125 + 0.025 * j - c[2], 0.0125 + 0.025 * k - c[3]
        local r = math.sqrt(x * x + y * y + z * z)
        if r <= R then ball = ball + 1 end
        if r > rin and r <= R then shell = shell + 1 end
        local inp = r <= rin
        if not inp and r <= R then
          inp = true
          for t = 1, #planes do
            local p = planes[t]
            if p[1] * x + p[2] * y + p[3] * z > p[4] then inp = false; break end
          end
        end
        if inp then inside = inside + 1 end
      end
    end
  end
  local a = sim:body{ material = rock, region = ico }
  local b = sim:body{ material = rock, region = lamina.ball{ center = c, radius = R } }
  print(string.format("icosphere3.obj (R = %g): %d particles; the half-space test %d; lamina.ball %d "
                      .. "(%d counted here); %d points between r_in = %.6g and R", R, #a, inside, #b, ball, shell, rin))
  assert(#b == ball, "lamina.ball's count is the lattice's")
  assert(#a == inside, "the mesh seeds exactly the points inside its facets")
  assert(math.abs(#a - #b) <= shell and shell > 0, "within the shell's points of the ball")
  print(string.format("  volume %.9g, the ball's %.9g (%.3g off)", ico.volume, 4 / 3 * math.pi * R^3,
                      ico.volume / (4 / 3 * math.pi * R^3) - 1))
end

-- 3. the icosphere as a membrane: the balloon
do
  local skin = lamina.membrane{ rho = 1000, E = 1e6, nu = 0.3, thickness = 1e-3, law = "plane_stress" }
  local h, r0, pr = 0.05, 0.3, 100
  local sim = lamina.sim{ dim = 3, domain = {0, 0, 0, 1, 1, 1}, cell = h, dt = 5e-4,
                          basis = "bspline2", scheme = "musl", boundary = { z0 = "free", z1 = "free" } }
  local mesh = lamina.mesh{ file = here .. "icosphere3.obj", scale = r0, translate = {0.5, 0.5, 0.5} }
  -- the cut: k = ceil(longest edge / spacing) for the whole mesh
  local L = 0
  for t = 1, mesh.triangles do
    local v = {mesh:triangle(t)}
    for e = 1, 3 do
      local ax, ay, az = mesh:vertex(v[e])
      local bx, by, bz = mesh:vertex(v[e % 3 + 1])
      L = math.max(L, math.sqrt((ax - bx)^2 + (ay - by)^2 + (az - bz)^2))
    end
  end
  local k = math.ceil(L / (h / 3) - 1e-9)
  local ne = 3 * mesh.triangles // 2
  local m = sim:membrane{ material = skin, spacing = h / 3, pressure = pr, damping = 200, surface = mesh }
  local expect = mesh.vertices + ne * (k - 1) + mesh.triangles * (k - 1) * (k - 2) // 2
  local p0 = m:particles()
  local A0 = 0
  for i = 1, p0.n do A0 = A0 + p0.area[i] end
  print(string.format("membrane on icosphere3.obj: longest edge %.5g, k = %d, %d points (expected %d), "
                      .. "area %.15g, the mesh's %.15g", L, k, #m, expect, A0, mesh.area))
  assert(#m == expect, "the cut's point count")
  assert(math.abs(A0 / mesh.area - 1) < 1e-12, "the points' areas sum to the mesh's")
  sim:step(300)
  local p = m:particles()
  local rm, Tm = 0, 0
  for i = 1, p.n do
    local r = math.sqrt((p.x[i] - 0.5)^2 + (p.y[i] - 0.5)^2 + (p.z[i] - 0.5)^2)
    rm = rm + r / p.n
    Tm = Tm + p.tension[i] / p.n
  end
  local worst = 0
  for i = 1, p.n do
    local dx, dy, dz = p.x[i] - 0.5, p.y[i] - 0.5, p.z[i] - 0.5
    local r = math.sqrt(dx * dx + dy * dy + dz * dz)
    worst = math.max(worst, math.abs(p.tension[i] / (pr * r / 2) - 1))
    assert(p.nx[i] * dx + p.ny[i] * dy + p.nz[i] * dz > 0, "outward normal at point " .. i)
  end
  local terr = Tm / (pr * rm / 2) - 1
  print(string.format("balloon from the mesh: r = %.6g, mean T / (p r / 2) - 1 = %.3g, every point within %.3g",
                      rm, terr, worst))
  assert(math.abs(terr) < 0.01, "mean tension within 1 % of p r / 2")
end

-- 4. binary STL
do
  local sim = lamina.sim{ dim = 3, domain = {0, 0, 0, 1, 1, 1}, cell = 0.05, dt = 1e-4 }
  local a = lamina.mesh{ file = here .. "cube.stl", scale = 0.4, translate = {0.3, 0.3, 0.3} }
  local b = lamina.mesh{ file = here .. "cube_binary.stl", scale = 0.4, translate = {0.3, 0.3, 0.3} }
  assert(a.vertices == b.vertices and a.triangles == b.triangles and a.volume == b.volume, tostring(b))
  for i = 1, a.vertices do
    local x1, y1, z1 = a:vertex(i)
    local x2, y2, z2 = b:vertex(i)
    assert(x1 == x2 and y1 == y2 and z1 == z2, "vertex " .. i)
  end
  local na, nb = #sim:body{ material = rock, region = a }, #sim:body{ material = rock, region = b }
  print(string.format("cube_binary.stl: %d particles, cube.stl %d", nb, na))
  assert(na == nb)
end

-- 5. an open mesh as a pre-tensioned sheet pinned at its edges
for _, spacing in ipairs{0.045, 0.03} do
  local skin = lamina.membrane{ rho = 1000, E = 1e6, nu = 0.3, thickness = 1e-3, law = "plane_stress" }
  local h, e0, L = 1 / 16, 0.01, 0.5
  local sim = lamina.sim{ dim = 3, domain = {0, 0, 0, 1, 1, 0.25}, cell = h, dt = 1e-3,
                          basis = "bspline2", scheme = "musl", boundary = { z0 = "free", z1 = "free" } }
  local sq = lamina.mesh{ file = here .. "square.obj", scale = {L, L, 1}, translate = {0.25, 0.25, 0.11} }
  assert(not sq.closed and math.abs(sq.area - L * L) < 1e-15, tostring(sq))
  local function edge(x, y) return x < 0.25 + 1e-9 or x > 0.75 - 1e-9 or y < 0.25 + 1e-9 or y > 0.75 - 1e-9 end
  -- pinned by a function, then by "edges" (the open mesh's rim)
  local m = sim:membrane{ material = skin, spacing = spacing, initial_strain = e0, surface = sq,
                          pin = spacing == 0.045 and function(x, y) return edge(x, y) end or "edges" }
  local k = math.ceil(math.sqrt(2) * L / spacing - 1e-9)
  assert(#m == (k + 1) * (k + 1), "points " .. #m .. ", k = " .. k)
  local T0 = 1e6 * 1e-3 * e0 / (1 - 0.3)
  local dev, vmax = 0, 0
  for _ = 1, 10 do
    sim:step(100)
    local p = m:particles()
    for i = 1, p.n do
      if not edge(p.x[i], p.y[i]) then dev = math.max(dev, math.abs(p.tension[i] / T0 - 1)) end
      vmax = math.max(vmax, math.sqrt(p.vx[i]^2 + p.vy[i]^2 + p.vz[i]^2))
      assert(math.abs(p.nz[i] - 1) < 1e-12, "normal +z")
    end
  end
  print(string.format("square.obj sheet, spacing %g (k = %d): %d points; tension off T0 by at most %.3g, "
                      .. "speed <= %.3g m/s over 1 s", spacing, k, #m, dev, vmax))
  assert(dev < 1e-12 and vmax < 1e-12, "at rest")
end
