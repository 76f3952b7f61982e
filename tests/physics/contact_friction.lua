-- A block sliding on an inclined plane with Coulomb friction (issue 14,
-- item 5; sim:contact law = "friction"). The plane is a slab held by
-- body:pin{points = "all"}, lying along x; gravity g = 10 is turned by theta
-- instead of the plane. Block 0.5 x 0.3 (E = 1e4, nu = 0.3, rho = 1, plane
-- strain), cell 0.1, 4 ppc, dt = 2e-4, uGIMP basis; the acceleration is the
-- least-squares slope of the block's velocity over t in [0.2, 0.6].
-- Checks: a = g (sin theta - mu cos theta) within 2 % for (theta, mu) =
-- (30, 0.3) and (45, 0.3); the block sticks (|v| < 1e-2 at t = 0.6) when
-- tan theta < mu (10 degrees, mu = 0.3); mu = 0 slides at g sin theta.
-- Measured (GIMP): 30/0.3 -0.32 %, 45/0.3 -0.67 %, mu = 0 -0.02 %. Not
-- reached, so not asserted here but in contact_friction_linear.lua (an
-- expected failure): the linear basis gives -5.8 % at 30/0.3, and mu = 0.6
-- at 45 degrees -15 % with GIMP (friction about 6-10 % too strong). With
-- bspline2 contact is refused (tests/bad/contact_bspline2.lua): among its
-- faults, a pinned plane's pin would hold the nodes one cell into the
-- block, which would not move.
local slide = require("contact_scenes").slide

for _, c in ipairs{ {30, 0.3}, {45, 0.3}, {30, 0} } do
  local a, exact = slide(c[1], c[2], "gimp")
  assert(math.abs(a - exact) <= 0.02 * exact,
         string.format("theta %g mu %g: a = %.4f, not within 2 %% of %.4f", c[1], c[2], a, exact))
end
local _, _, v = slide(10, 0.3, "gimp")
assert(v < 1e-2, "tan theta < mu: the block should stick, moves at " .. v)
