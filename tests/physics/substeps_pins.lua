-- Issue 36 item 1: multi-rate stepping (lamina.sim{substeps}) with point
-- pins (src/mpm/subcycle_terms.c: the held point's mass off the membranes'
-- sums, the constraint solved, the point moved with its pin, at every
-- sub-step). The string of assets/lua/string_modes.lua held by two pins
-- (tests/physics/string_pinned.lua), mode 1, cell 1/32, on the lumped mass
-- (sub-stepping is lumped only):
-- 1. stepping 4 x its 0.4 h / c with 4 sub-steps: within 1 % of
--    f_1 = (1 / 2L) sqrt(T / mu) and within 0.1 % of the plain step's
--    frequency (without gas the sub-steps are the plain steps of dt / k),
--    the total energy within 1 % of the largest kinetic energy;
-- 2. substeps = 1 is the plain step: the same frequency error and energy
--    to 1e-9.
-- Measured (2026-12-05): see the printed lines (plain and 4 sub-steps).
local sm = require("string_modes")

local plain = sm.run{ ends = "pins", mode = 1, basis = "bspline2", mass = "lumped" }
local sub = sm.run{ ends = "pins", mode = 1, basis = "bspline2", substeps = 4 }
local one = sm.run{ ends = "pins", mode = 1, basis = "bspline2", substeps = 1 }
for name, r in pairs{ plain = plain, substeps = sub } do
  assert(math.abs(r.err) < 0.01, string.format("pinned string, %s: frequency off by %.3f %%", name,
                                               100 * r.err))
  assert(r.de < 0.01, string.format("pinned string, %s: energy changed by %.3f %% of the largest KE",
                                    name, 100 * r.de))
end
assert(math.abs(sub.err - plain.err) < 1e-3,
       string.format("pinned string: the sub-steps changed the frequency by %.4f %%",
                     100 * (sub.err - plain.err)))
assert(math.abs(one.err - plain.err) < 1e-9 and math.abs(one.de - plain.de) < 1e-9,
       string.format("substeps = 1: frequency error %.12g vs %.12g, energy %.12g vs %.12g",
                     one.err, plain.err, one.de, plain.de))
