-- V7 dog-bone at cell 0.05 ([F] Table III-IV row 4, [T] Table 5), reduced
-- to t = 1.5 (the gallery runs it to t = 4). With the papers' continuity
-- density the scheme alone fails here (pure FLIP at t = 0.58: viscously
-- heated gas beside the membrane thins out until a point slips through).
-- Two ways through, both checked:
--  * gas splitting (lamina.gas{split = 16}, as the gallery page;
--    docs/decisions.md "Gas splitting");
--  * [T]'s quadratic cell density (lamina.gas{density = "quadratic"}, eq
--    4.6), no splitting: the density follows the points' spacing (with
--    continuity it drifts low, so the viscous stress acts on too large a
--    volume - the likely reason, not proven; docs/decisions.md "Gas
--    pressure over the space").
-- Checks (issue 8, cells <= 0.1): no gas outside the membrane at any
-- sample; over [0.5, 1.5] the radius at 0 and 90 degrees within 1 % of each
-- other and the hoop stress within 5 % of p r / t, p the mean over the
-- enclosed space (gas:pressure(mem)). Measured (one thread, 122 s and 70 s
-- here): split: r(0) 1.3868, r(90) 1.3823, hoop -1.4 %, 31 213 gas points at
-- the end (11 443 at the start); quadratic: r(0) 1.3941, r(90) 1.3849,
-- hoop -1.9 %, no point split. The gallery's
-- split run to t = 4: +0.2 % over [3, 4]; quadratic to t = 4: r(0) = r(90) =
-- 1.4085, p 28.47, no gas out.
-- every gas particle outside the membrane: membrane:escaped's count beyond a
-- quarter cell plus its skin-grazers (issue 30: the count this file used)
local function outside(beyond, _, grazing) return beyond + grazing end
local dog = require("dogbone")
local t_end = 1.5

local function run(name, o)
  local sim, gas, mem = dog.setup(0.05, o)
  local n0, escaped = #gas, 0
  local rec = sim:record{ every = 0.01, values = {
    p = function() return gas:pressure(mem) end,
    hoop = function() return mem:hoop_stress() end,
    r0 = function() return mem:radius_at(0) end,
    r90 = function() return mem:radius_at(90) end,
    escaped = function() escaped = math.max(escaped, outside(mem:escaped(gas))); return escaped end } }
  sim:run{ t_end = t_end }
  local t0 = 0.5
  local p, hoop = rec:mean("p", t0, t_end), rec:mean("hoop", t0, t_end)
  local r0, r90 = rec:mean("r0", t0, t_end), rec:mean("r90", t0, t_end)
  local prt = p * 0.5 * (r0 + r90) / 0.1
  print(string.format("V7 cell 0.05 to t = %.1f, %s: %d gas points (%d at the start), r(0) %.4f "
    .. "r(90) %.4f p %.2f hoop %.1f vs p r / t %.1f (%+.2f %%), gas outside %d", t_end, name, #gas,
    n0, r0, r90, p, hoop, prt, 100 * (hoop - prt) / prt, escaped))
  assert(escaped == 0, name .. ": gas escaped the membrane")
  assert(math.abs(r0 - r90) / r0 <= 0.01, name .. ": not circular")
  assert(math.abs(hoop - prt) / prt <= 0.05, name .. ": hoop stress not within 5 % of p r / t")
  return #gas > n0
end

assert(run("split", { split = 16 }), "split: no gas point was split")
run("quadratic density", { density = "quadratic" })
