-- V7 dog-bone membrane expansion ([F] §4.3, Tables III-IV; [T] §6.2,
-- Table 5; physics.md V7), reduced: cells 0.4 / 0.2 / 0.1 to t = 2.5
-- (the gallery adds 0.05 and runs to t = 4). The construction of the shape
-- (not given numerically in the papers) is in assets/lua/dogbone.lua;
-- scripts/paper/gas_dogbone.lua says why.
-- Checks (issue 8): gas contained at every refinement; at cell 0.1 the
-- final shape is circular (radius at 0 and 90 degrees within 1 %) and the
-- time-averaged hoop stress within 5 % of p r / t; final radius and
-- pressure converge with refinement (the radius grows towards the taut
-- radius 1.40 and the steps shrink, the pressure falls towards the energy
-- balance's 29.0 and the steps shrink).
-- Expected failure, measured and reported rather than hidden: the papers'
-- energy loss shrinks with refinement; here the total energy rises by
-- 0.7 / 1.0 / 1.2 % (cells 0.4 / 0.2 / 0.1, to t = 4) - FLIP velocity noise
-- of the light membrane points (their kinetic energy stays ~2 at rest).
local dog = require("dogbone")
local t_end = 2.5

local function expand(h)
  local sim, gas, mem = dog.setup(h)
  local escaped = 0
  local rec = sim:record{ every = 0.01, energy = true, values = {
    p = function() return gas:pressure() end,
    hoop = function() return mem:hoop_stress() end,
    r0 = function() return mem:radius_at(0) end,
    r90 = function() return mem:radius_at(90) end,
    escaped = function() escaped = math.max(escaped, mem:escaped(gas)); return escaped end } }
  sim:run{ t_end = t_end }
  local t0 = t_end - 1
  local r = { p = rec:mean("p", t0, t_end), hoop = rec:mean("hoop", t0, t_end),
              r0 = rec:mean("r0", t0, t_end), r90 = rec:mean("r90", t0, t_end), escaped = escaped }
  local tot = rec:column("total")
  r.dE = (tot[#tot] - tot[1]) / tot[1]
  r.r = 0.5 * (r.r0 + r.r90)
  r.prt = r.p * r.r / 0.1
  print(string.format("V7 cell %.2f: r(0) %.4f r(90) %.4f p %.2f hoop %.1f vs p r / t %.1f "
    .. "(%+.1f %%), gas outside %d, energy %+.2f %%", h, r.r0, r.r90, r.p, r.hoop, r.prt,
    100 * (r.hoop - r.prt) / r.prt, escaped, 100 * r.dE))
  return r
end

local a, b, c = expand(0.4), expand(0.2), expand(0.1)
for _, r in ipairs{a, b, c} do assert(r.escaped == 0, "gas escaped the membrane") end
assert(math.abs(c.r0 - c.r90) / c.r0 <= 0.01, "cell 0.1: not circular")
assert(math.abs(c.hoop - c.prt) / c.prt <= 0.05, "cell 0.1: hoop stress not within 5 % of p r / t")
assert(a.r < b.r and b.r < c.r and c.r - b.r < b.r - a.r, "radius not converging")
assert(a.p > b.p and b.p > c.p and b.p - c.p < a.p - b.p, "pressure not converging")
if not (c.dE < b.dE and b.dE < a.dE) then
  print(string.format("EXPECTED FAILURE (reported): energy change does not fall with refinement: "
    .. "%+.2f / %+.2f / %+.2f %%", 100 * a.dE, 100 * b.dE, 100 * c.dE))
end
