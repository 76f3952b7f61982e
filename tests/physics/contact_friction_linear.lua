-- EXPECTED FAILURE (tests/CMakeLists.txt: WILL_FAIL): the inclined plane of
-- contact_friction.lua where lamina's friction is too strong. Measured:
-- linear basis, theta 30, mu 0.3: a = 2.262 against 2.402 (-5.8 %); uGIMP,
-- theta 45, mu 0.6: a = 2.391 against 2.828 (-15.5 %). The excess (an
-- effective mu 6-10 % above the given one) is not explained yet; a likely
-- part: the normal impulse at each contact node is counted per node, and
-- where friction's torque pulls the trailing edge up the correction still
-- holds it down, a tensile impulse that more pressure at the leading edge,
-- with more friction, must balance. Measured 2026-12-02 (fifth session,
-- an instrumented build summing, over the block's friction nodes and the
-- run to t = 0.6, its normal impulse m max(w_n, 0) and the friction
-- impulse m (1 - s) |w_t|): the friction is exactly mu times the normal
-- impulse counted (0.415 = 0.6 x 0.692), but that count exceeds the
-- weight's share M g cos(theta) t (0.636 at 45 degrees) by 8.8 % at
-- mu 0.6 (uGIMP), 1.0 % at mu 0.3 (uGIMP, within 2 %) and 3.8 % with the
-- linear basis at 30 degrees (0.809 against 0.779), while the block's own
-- normal momentum gains only 1 % of it: the Coulomb law is right, the
-- normal impulse per node is over-counted (a normal tilted at the block's
-- corners reads some of the sliding speed as approach, or approach and
-- parting rectified node by node). This script asserts the issue's 2 %.
local slide = require("contact_scenes").slide
local ok = true
for _, c in ipairs{ {30, 0.3, "linear"}, {45, 0.6, "gimp"} } do
  local a, exact = slide(c[1], c[2], c[3])
  ok = ok and math.abs(a - exact) <= 0.02 * exact
end
assert(ok, "friction block not within 2 % of g (sin theta - mu cos theta)")
