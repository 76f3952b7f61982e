-- EXPECTED FAILURE (tests/CMakeLists.txt: WILL_FAIL): the inclined plane of
-- contact_friction.lua where lamina's friction is too strong. Measured:
-- linear basis, theta 30, mu 0.3: a = 2.262 against 2.402 (-5.8 %); uGIMP,
-- theta 45, mu 0.6: a = 2.391 against 2.828 (-15.5 %). The excess (an
-- effective mu 6-10 % above the given one) is not explained yet; a likely
-- part: the normal impulse at each contact node is counted per node, and
-- where friction's torque pulls the trailing edge up the correction still
-- holds it down, a tensile impulse that more pressure at the leading edge,
-- with more friction, must balance. This script asserts the issue's 2 %.
local slide = require("contact_scenes").slide
local ok = true
for _, c in ipairs{ {30, 0.3, "linear"}, {45, 0.6, "gimp"} } do
  local a, exact = slide(c[1], c[2], c[3])
  ok = ok and math.abs(a - exact) <= 0.02 * exact
end
assert(ok, "friction block not within 2 % of g (sin theta - mu cos theta)")
