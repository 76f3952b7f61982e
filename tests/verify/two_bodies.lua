-- Verification case (issue 30 item 1): two bodies approaching in one
-- velocity field (lamina's default: no sim:contact pair). Two elastic bars
-- 1 x 2 (E = 1e4, rho = 1, nu = 0.3, plane stress, 4 points a cell), the
-- left one moving right at 1, the right one at rest, 1.0 apart (their
-- material edges: the region boundaries).
-- Exact: in one grid field ([M] §4.1) two bodies exchange momentum as soon
-- as a grid node lies in the stencil of a particle of each, not when they
-- touch. A particle's stencil reaches r from it: r = h (linear), h + l_p
-- (uGIMP, l_p = h / (2 sqrt(ppc)) = h/4 here), 1.5 h (quadratic B-spline,
-- the default), the weight zero at r itself. So with their nearest
-- particles d apart, the bodies can share a node only while d < 2r, and
-- certainly do once the interval (x_R - r, x_L + r), 2r - d long, is longer
-- than a cell. Their material edges lie half a particle spacing s = h /
-- sqrt(ppc) outside the nearest particles, so the gap g = d - s at which
-- they start to interact is
--   2r - h - s <= g < 2r - s     (the documented distance, docs/api.md
--                                 sim:contact: 2.5 cells at 4 points a cell
--                                 on the default, 1.5 linear, 2 uGIMP),
-- where in that cell-wide range it falls depending on where the nodes lie.
-- For this scene it is exact: the first node x_i = k h within r of the
-- right bar's nearest particle x_R that the left's, x_L + travel, comes
-- within r of, g = 1 - (x_i - r - x_L): 0.5625 = 2.25 cells on the default
-- at cell 0.25 (0.1875 linear, 0.25 uGIMP). Measured: the gap at the first
-- step after which the right bar has any momentum (|p| > 1e-12 of the
-- left's), its difference from that g in per cent of a cell (MUSL passes the
-- shared node's velocity to the right bar's stress a step or two later:
-- about 0.6 % of a cell at cell 0.25). With tol > 0 it also asserts that
-- the interaction starts no farther apart than the documented distance
-- 2r - s and no nearer than 2r - h - s. Resolution: level 1, 2 = cell
-- 0.25, 0.125.
local V = require("lib.vcase")
local h = 0.5 / 2 ^ V.level
local ppc = 4
local sim = V.sim{ domain = {0, 0, 4, 5}, cell = h, dt = 0.2 * h / 100 }
local mat = lamina.elastic{ rho = 1, E = 1e4, nu = 0.3, plane = "stress" }
local left = sim:body{ material = mat, ppc = ppc, velocity = {1, 0},
                       region = lamina.rect{ min = {0.5, 1.5}, max = {1.5, 3.5} } }
local right = sim:body{ material = mat, ppc = ppc, region = lamina.rect{ min = {2.5, 1.5}, max = {3.5, 3.5} } }
-- The stencil's reach and the predicted onset (the header's derivation).
local s = h / math.sqrt(ppc)
local reach = ({ linear = h, gimp = h + s / 2, bspline2 = 1.5 * h })[sim.basis]
assert(reach, "two_bodies: no stencil reach known for basis " .. tostring(sim.basis))
local function extreme(body, pick)
  local q, x = body:particles(), nil
  for i = 1, q.n do x = x and pick(x, q.x[i]) or q.x[i] end
  return x
end
local xL, xR = extreme(left, math.max), extreme(right, math.min)
local onset
for k = math.floor((xR - reach) / h), math.ceil((xR + reach) / h) do
  local xi = k * h
  if math.abs(xi - xR) < reach then
    local g = 1.0 - (xi - reach - xL)
    onset = math.max(onset or g, g)
  end
end
local doc_far, doc_near = 2 * reach - s, 2 * reach - h - s
local x0 = left:com()
local p0 = left:mass() * 1
local gap
sim:every(sim.dt, function()
  if gap then return end
  local vx, vy = right:velocity()
  if math.sqrt(vx * vx + vy * vy) * right:mass() > 1e-12 * p0 then
    gap = 1.0 - (left:com() - x0)
  end
end)
sim:run{ t_end = 1.2 }
V.result{ quantity = "interaction_gap", value = gap or 0, exact = onset, scale = h, h = h }
if V.tol > 0 then
  assert(gap and gap <= doc_far + 1e-9 and gap >= doc_near - 0.01 * h, string.format(
    "two_bodies: they start to interact %.4g cells apart, outside the documented %.4g-%.4g cells",
    (gap or 0) / h, doc_near / h, doc_far / h))
end
