-- The two-bar impact of [M] §4.1-4.2 with contact-release against an
-- independent reference (ours): a finite-element bar against a rigid
-- frictionless wall (assets/lua/bar_wall_fem.lua says why the two are the
-- same problem in the frame of the centre of mass). The bars' velocities at
-- t = 0.5 give the coefficient of restitution e = (v_right - v_left) / v0.
--
-- The reference: bilinear elements of size h_e, e = 0.889 (h_e 0.125),
-- 0.915 (0.0625), 0.930 (0.03125), 0.9385 (0.015625): converging to about
-- 0.95, a 2D bar keeping a few per cent of the energy in vibration. The
-- paper's 0.3 / 1.7 (e = 0.7, [M] Fig 20, [T] Fig 95, with an 11 % energy
-- loss, [T] A.1.5) is its own numerical dissipation; its Fig 20(c) has the
-- difference growing with refinement, as here.
--
-- Checks, for the MPM cell h = 0.25 (the deck's) and 0.125, against the
-- elements of size h/2 (the MPM's particle spacing at 4 points per cell):
--  * |e_MPM(h) - e_FEM(h/2)| <= 0.02: the reference's own accuracy at that
--    size: its kinematic wall loses 4.1 % of the energy at h_e = 0.125
--    (2.3 % at 0.0625), i.e. about 2 % of e (kinetic energy goes as e^2);
--    its step matters as much: 0.9127, 0.9150, 0.9256 at 0.25, 0.5 and 0.9
--    of the stable step, elements of 0.0625 (0.5 here);
--  * e_MPM grows with refinement, and the finer mesh is nearer the finest
--    reference (convergence, [M] Fig 20c).
local F = require("bar_wall_fem")
local scenes = require("contact_scenes")
local function fem(h)
  return (F.rebound{ lx = 1.25, ly = 4.5, h = h, E = 1e5, nu = 0.3, rho = 1, plane = "stress",
                     v = 1, t_end = 0.02 })
end
local function mpm(cell)
  local sim, l, r = scenes.two_bar{ cell = cell, release = true }
  sim:run{ t_end = 0.5 }
  return (r:velocity() - l:velocity()) / 2
end
local ref = { [0.25] = fem(0.125), [0.125] = fem(0.0625) }
local got = { [0.25] = mpm(0.25), [0.125] = mpm(0.125) }
for _, h in ipairs{ 0.25, 0.125 } do
  print(string.format("cell %g: e = %.4f (left %.4f, right %.4f); reference, elements %g: "
    .. "e = %.4f; difference %.4f", h, got[h], 1 - got[h], 1 + got[h], h / 2, ref[h], got[h] - ref[h]))
end
for _, h in ipairs{ 0.25, 0.125 } do
  assert(math.abs(got[h] - ref[h]) <= 0.02, string.format(
    "cell %g: e = %.4f, the reference's %.4f (tolerance 0.02)", h, got[h], ref[h]))
end
-- uGIMP, the other basis contact runs on (the quadratic B-spline is refused:
-- tests/bad/contact_bspline2.lua), at cell 0.125 (at 0.25 its 1.5-cell
-- stencil reaches the deck's fixed walls, a quarter from the bars' ends)
do
  local sim, l, r = scenes.two_bar{ cell = 0.125, release = true, basis = "gimp" }
  sim:run{ t_end = 0.5 }
  local e = (r:velocity() - l:velocity()) / 2
  print(string.format("gimp, cell 0.125: e = %.4f; reference %.4f", e, ref[0.125]))
  assert(math.abs(e - ref[0.125]) <= 0.02, "gimp: e = " .. e)
  assert(math.abs(l:velocity() + r:velocity() - 2) <= 1e-12, "gimp: momentum")
end
assert(got[0.125] > got[0.25], "e did not grow with refinement")
assert(math.abs(got[0.125] - ref[0.125]) < math.abs(got[0.25] - ref[0.125]),
       "the finer mesh is not nearer the finest reference")
