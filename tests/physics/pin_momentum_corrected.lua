-- Issue 30 items 2-3: a pin's reaction stays exact under
-- lamina.sim{mass = "corrected"} (src/mpm/mass_corrected.c solves the pins'
-- constraint inside its Neumann step; constraint.c adds both force solves'
-- impulses to the reaction). tests/physics/pin_momentum.lua's string (L = 1,
-- T = 5, cell 1/32, points half a cell apart, gravity 10, held at rest at
-- its right end, driven at its left at (0.02 cos 7t, 0.05 sin 9t)), 2000
-- steps: sum m v over its points changes by (reactions + weight) dt to
-- rounding. Measured 1.28e-13 of the largest reaction (30.2); before the
-- constraint went inside the correction the balance failed (the pins'
-- reaction missed what the correction moved). The driven point follows its
-- pin exactly, the held one does not move.
local worst, largest, dlx, dly, drx, dry = require("pinned_string").balance{mass = "corrected"}
print(string.format("corrected mass: momentum balance off by %.3e of the largest reaction %.4g; driven end off by %.2e, %.2e; held end moved %.2e, %.2e",
                    worst / largest, largest, dlx, dly, drx, dry))
assert(worst < 1e-9 * largest, "the reactions do not balance the string's momentum change")
assert(math.abs(dlx) < 1e-12 and math.abs(dly) < 1e-12, "the driven end did not follow its pin")
assert(drx == 0 and dry == 0, "the held end moved")
