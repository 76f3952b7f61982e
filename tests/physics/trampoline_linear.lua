-- Expected failure (tests/CMakeLists.txt WILL_FAIL), issue 30 item 3: the
-- trampoline (assets/lua/trampoline.lua) on the papers' linear basis with
-- segment forces, 1 s: the total energy within 1 % above its start.
-- Measured +2.26 % (min -2.33 %); the same scene with the sheet's ends on
-- fixed walls instead of pins (domain x 0.2 .. 1.8): +2.31 %, so the gain
-- is not the pins' but the ball's (E 1e6 hypoelastic, 4 points a cell:
-- the bilinear basis' cell-crossing noise, docs/robustness.md "Energy
-- growth of a moving body on the bilinear basis"; GIMP: pins +1.97 %,
-- walls +1.75 %; the defaults: pins +0.27 %, walls +0.28 %). The
-- node-holding pins passed it before by draining the scene (+0.53 %).
local tramp = require("trampoline")
local sim, _, ball = tramp.setup{force = "segment", basis = "linear"}
local w = tramp.watch(sim, ball)
sim:run{t_end = 1.0}
local rise = w.e_max / w.e0 - 1
print(string.format("linear, segment: energy %.4f -> max %.4f (%+.4f %%)", w.e0, w.e_max, 100 * rise))
assert(w.vy_min < -1.5 and w.vy_max > 1.0 and w.y_min > 0.2, "the ball did not bounce")
assert(rise <= 0.01, string.format("total energy rose %.3f %% (limit 1 %%)", 100 * rise))
