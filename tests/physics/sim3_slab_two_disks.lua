-- The 2D two-disk impact run as a one-cell-thick 3D slab (issue 34 item 3;
-- docs/3d.md "Tests", physics 2): tests/physics/two_disks.lua's scene
-- (disks of radius 0.2 at (0.25, 0.25) and (0.75, 0.75), velocities
-- +-(0.1, 0.1), E = 1000, nu = 0.3, rho = 1000, cell 0.05, 2 x 2 points a
-- cell, MUSL, dt = 1e-3) through the Lua API twice: lamina.sim{} in plane
-- strain, and lamina.sim{dim = 3} with the disks as cylinders one cell
-- thick between symmetry faces z0 and z1 (1 point through the thickness,
-- at mid-cell), which is plane strain. The two engines share no step code
-- (sim3_*.c against step*.c), so agreement to rounding checks the 3D
-- step, walls and law against the 2D ones through everything the API
-- adds (seeding, materials, bodies, the clock).
-- Compared every 0.1 s to t = 3 (the impact and the separation): each
-- particle's x, y; v_z and z exactly as seeded; the energies per unit
-- depth (3D / h). Both bases.
-- Measured (to t = 3, the disks apart again): positions to 1.3e-15 m
-- (linear) and 4.4e-16 m (bspline2), energies to 1.8e-14 / 1.9e-15 of the
-- total; the slab's z and v_z exactly as seeded.
local h = 0.05
local function scene2(basis)
  local sim = lamina.sim{ basis = basis, domain = {0, 0, 1, 1}, cell = h, dt = 1e-3,
                          scheme = "musl" }
  local m = lamina.elastic{ rho = 1000, E = 1000, nu = 0.3, plane = "strain" }
  local a = sim:body{ material = m, ppc = 4, velocity = {0.1, 0.1},
                      region = lamina.disk{ center = {0.25, 0.25}, radius = 0.2 } }
  local b = sim:body{ material = m, ppc = 4, velocity = {-0.1, -0.1},
                      region = lamina.disk{ center = {0.75, 0.75}, radius = 0.2 } }
  return sim, {a, b}
end
local function scene3(basis)
  local sim = lamina.sim{ dim = 3, basis = basis, domain = {0, 0, 0, 1, 1, h}, cell = h,
                          dt = 1e-3, scheme = "musl",
                          boundary = { x0 = "fixed", x1 = "fixed", y0 = "fixed", y1 = "fixed",
                                       z0 = "symmetry", z1 = "symmetry" } }
  local m = lamina.elastic{ rho = 1000, E = 1000, nu = 0.3 }
  local a = sim:body{ material = m, ppc = {2, 2, 1}, velocity = {0.1, 0.1, 0},
                      region = lamina.cylinder{ from = {0.25, 0.25, 0}, to = {0.25, 0.25, h},
                                                radius = 0.2 } }
  local b = sim:body{ material = m, ppc = {2, 2, 1}, velocity = {-0.1, -0.1, 0},
                      region = lamina.cylinder{ from = {0.75, 0.75, 0}, to = {0.75, 0.75, h},
                                                radius = 0.2 } }
  return sim, {a, b}
end

for _, basis in ipairs{"linear", "bspline2"} do
  local s2, b2 = scene2(basis)
  local s3, b3 = scene3(basis)
  for i = 1, 2 do
    assert(#b2[i] == 208 and #b3[i] == 208,
           basis .. ": seeding gave " .. #b2[i] .. " and " .. #b3[i] .. " points, expected 208")
  end
  local dx, de, zoff, ke = 0, 0, 0, 0
  local e0 = s2:energy().total
  for k = 1, 30 do
    s2:run{ t_end = 0.1 * k }
    s3:run{ t_end = 0.1 * k }
    assert(s2.nstep == s3.nstep, "the clocks differ: " .. s2.nstep .. " and " .. s3.nstep)
    for i = 1, 2 do
      local p, q = b2[i]:particles(), b3[i]:particles()
      for j = 1, p.n do
        dx = math.max(dx, math.abs(p.x[j] - q.x[j]), math.abs(p.y[j] - q.y[j]))
        zoff = math.max(zoff, math.abs(q.z[j] - 0.5 * h), math.abs(q.vz[j]))
      end
    end
    local e2, e3 = s2:energy(), s3:energy()
    for _, key in ipairs{"kinetic", "strain", "total"} do
      de = math.max(de, math.abs(e3[key] / h - e2[key]) / e0)
    end
    ke = math.max(ke, e2.kinetic)
  end
  local e2 = s2:energy()
  print(string.format("%-8s t = %.2f: positions differ by %.2g m, energies by %.2g of the "
    .. "total (kinetic %.4g -> %.4g J/m, strain %.3g J/m), z and v_z off by %.2g",
    basis, s2.t, dx, de, e0, e2.kinetic, e2.strain, zoff))
  assert(dx <= 1e-12, basis .. ": the slab's positions differ from the 2D run's by " .. dx)
  assert(de <= 1e-10, basis .. ": the slab's energies differ from the 2D run's by " .. de)
  assert(zoff == 0, basis .. ": the slab moved out of its plane by " .. zoff)
end
