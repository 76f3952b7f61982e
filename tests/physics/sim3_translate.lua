-- A 3D block translating (issue 34 item 3; docs/3d.md "Tests", physics 1):
-- a block of 4 x 3 x 2 cells, 8 points a cell, moving at v = (0.3, -0.2, 0.1)
-- in a box larger than its path, no gravity. A uniform velocity has no
-- gradient: the stress must stay zero to rounding, the momentum equal its
-- start, and the centre of mass follow x0 + v t. Through the Lua API
-- (lamina.sim{dim = 3}), under MUSL with both bases and USL with the
-- quadratic B-spline. USL with the trilinear hats is the known small-mass
-- failure (docs/3d.md "Tests (issue 34 item 3)": its expected failure,
-- unit.test_sim3_usl_trilinear),
-- not run here.
-- Measured (200 steps): |sigma| <= 3.0e-11 Pa (E = 1e6: 3e-17 of E),
-- momentum to 3.6e-15 relative, path to 7.5e-15 m, in all three runs.
local v = {0.3, -0.2, 0.1}
local function run(scheme, basis)
  local sim = lamina.sim{ dim = 3, domain = {0, 0, 0, 2, 2, 2}, cell = 0.1, dt = 1e-3,
                          scheme = scheme, basis = basis, boundary = "fixed" }
  local rock = lamina.elastic{ rho = 1000, E = 1e6, nu = 0.3 }
  local block = sim:body{ material = rock, ppc = 8, velocity = v,
                          region = lamina.box{ x0 = 0.5, y0 = 0.8, z0 = 0.7,
                                               x1 = 0.9, y1 = 1.1, z1 = 0.9 } }
  assert(#block == 4 * 3 * 2 * 8, "seeding: " .. #block .. " points, expected 192")
  local m = block:mass()
  local x0 = {block:com()}
  sim:step(200)
  local p = block:particles()
  local smax = 0
  for _, k in ipairs{"sxx", "syy", "szz", "syz", "sxz", "sxy"} do
    for i = 1, p.n do smax = math.max(smax, math.abs(p[k][i])) end
  end
  local P = {sim:momentum()}
  local c = {block:com()}
  local dp, dx = 0, 0
  for a = 1, 3 do
    dp = math.max(dp, math.abs(P[a] - m * v[a]) / (m * 0.3))
    dx = math.max(dx, math.abs(c[a] - (x0[a] + v[a] * sim.t)))
  end
  local e = sim:energy()
  print(string.format("%-4s %-8s |sigma| <= %.2g Pa, momentum %.2g rel, path %.2g m, "
    .. "strain energy %.2g J, kinetic %.6g J", scheme, basis, smax, dp, dx, e.strain, e.kinetic))
  assert(smax <= 1e-9, scheme .. " " .. basis .. ": stress " .. smax .. " Pa in a rigid translation")
  assert(dp <= 1e-12, scheme .. " " .. basis .. ": momentum changed by " .. dp)
  assert(dx <= 1e-12, scheme .. " " .. basis .. ": the centre of mass is off its path by " .. dx)
  assert(math.abs(e.kinetic - 0.5 * m * (0.09 + 0.04 + 0.01)) <= 1e-12 * e.kinetic,
         "kinetic energy changed: " .. e.kinetic)
end
run("musl", "linear")
run("musl", "bspline2")
run("usl", "bspline2")
