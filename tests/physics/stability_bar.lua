-- The stable step of [T] §8.5 (Box 14's bar, assets/lua/stability_bar.lua;
-- the gallery page scripts/paper/stability_bar.lua): energy against time
-- for dt = factor h/c, unstable when the run fails or the energy passes
-- 1e4 x its start within t = 1 (1000 CFL steps).
-- [T] §8.5: the first unstable factor was 2.0 with the points at the cell
-- centres and 1.1 at the cell sides (the analysis, eq 8.41: 2 and 1).
-- Measured (MUSL) on the list below: centres 2.2 (2.1 stable, with a 289x
-- transient; 2.15 unstable on a finer list), sides 1.1 (1.05 stable, 256x
-- transient). Sides: asserted in (1.0, 1.1]. Centres: [T]'s 2.0 is not
-- reached — lamina stays stable one entry longer — so (2.0, 2.1] is an
-- expected failure, printed, and the measured 2.2 asserted so a change shows.
-- USL, measured: centres 0.9 on this list (0.75 on a finer one), sides 0.5
-- (unstable at every factor down to 0.1: the nearly empty end node at x = 5).
local bar = require("stability_bar")
local factors = { 0.5, 0.9, 1.0, 1.05, 1.1, 1.5, 1.9, 2.0, 2.1, 2.2 }

local _, sides = bar.scan("sides", "musl", factors, 1.0)
local _, centres = bar.scan("centres", "musl", factors, 1.0)
local _, usl_c = bar.scan("centres", "usl", factors, 1.0)
local _, usl_s = bar.scan("sides", "usl", factors, 1.0)
print(string.format("first unstable dt c/h: MUSL sides %s (paper 1.1), centres %s (paper 2.0); "
  .. "USL centres %s, sides %s", sides, centres, usl_c, usl_s))
assert(sides and sides > 1.0 and sides <= 1.1,
       "MUSL, points at the cell sides: first unstable " .. tostring(sides) .. ", [T] 1.1")
if not (centres and centres > 2.0 and centres <= 2.1) then
  print(string.format("expected failure: MUSL, points at the cell centres: first unstable %s "
    .. "h/c, [T] §8.5 2.0 (lamina stays stable at 2.1)", tostring(centres)))
end
assert(centres == 2.2, "MUSL centres: measured 2.2, now " .. tostring(centres)
       .. "; update docs/robustness.md and this test")
assert(usl_c == 0.9, "USL centres changed: " .. tostring(usl_c))
assert(usl_s == 0.5, "USL sides changed: " .. tostring(usl_s))

-- Why 2.2 and not 2.0 (issue 32 item 2): the limit itself, bisected, is
-- 2.103-2.105 h/c for Box 14's five points at the cell centres and
-- 1.051-1.053 at the sides, both 5 % above eq 8.41's 2 and 1; a longer bar
-- (41 points, one a cell, the middle one perturbed) comes within 0.3 % of
-- them (measured 2.001-2.003 and 1.001-1.002). The analysis is the
-- infinite lattice's, whose shortest wave a five-point bar with free ends
-- cannot hold: its highest mode is slower, so its limit is higher. Checked
-- against [T] §8.5's "factors of 2.0 and 1.0" to half the printed digit,
-- and the five-point bar's limit is asserted to stay above 2.05 (so [T]'s
-- observed 2.0 is not lamina's five-point bar: its sweep's steps and
-- criterion are not in the text).
local c5 = { bar.limit("centres", "musl", 5, 1.8, 2.3, 8, 1.0) }
local s5 = { bar.limit("sides", "musl", 5, 0.9, 1.2, 8, 1.0) }
local c41 = { bar.limit("centres", "musl", 41, 1.8, 2.3, 8, 1.0) }
local s41 = { bar.limit("sides", "musl", 41, 0.9, 1.2, 8, 1.0) }
print(string.format("limit dt c/h: 5 points centres %.4f-%.4f, sides %.4f-%.4f; "
  .. "41 points centres %.4f-%.4f, sides %.4f-%.4f", c5[1], c5[2], s5[1], s5[2],
  c41[1], c41[2], s41[1], s41[2]))
assert(math.abs(0.5 * (c41[1] + c41[2]) - 2.0) <= 0.05, "41-point bar, centres: limit off eq 8.41's 2.0")
assert(math.abs(0.5 * (s41[1] + s41[2]) - 1.0) <= 0.05, "41-point bar, sides: limit off eq 8.41's 1.0")
assert(c5[1] > 2.05 and s5[1] > 1.0, "five-point bar: limits moved (measured 2.103 / 1.051)")
assert(c41[2] < c5[1] and s41[2] < s5[1], "the longer bar's limits are not below the five-point bar's")
