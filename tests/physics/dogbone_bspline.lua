-- Issue 13 item 6: the slack dog-bone ([T] §6.2; assets/lua/dogbone.lua's
-- construction) at cell 0.05 runs to t = 4 with no gas splitting and no gas
-- out, with the quadratic B-spline and the papers' point forces (the best
-- option for it: docs/robustness.md "Which default") - where the bilinear
-- basis fails at t = 0.58 without splitting. Labelled heavy (about 5 min on
-- two threads, idle): the gallery page gas_dogbone_bspline shows the same
-- run. Checks: no gas particle outside the membrane at any sample (every
-- 0.01); over [3, 4] r(0), r(90) and the space-mean pressure against [T]
-- Table 5 (1.394, 1.396, 29.0), within the spread between [T] Table 5 and
-- [F] Table III at this cell (0.034 and 2.7: the papers' own difference);
-- the mean hoop stress within 5 % of p r / t of the same run (ours; the V7
-- test's tolerance, [F] Table IV reports 2-5 %). Measured (two threads):
-- r 1.394 / 1.394, p 29.23, hoop -0.82 %, no gas out.
-- Then the defaults (segments) on the same dog-bone, 90 points, printed as
-- measured, not asserted: they run and match Table 5 but let up to 3 gas
-- particles past the chords (by at most 0.02 cells) while the membrane
-- snaps taut, t < 0.1 (docs/robustness.md "Which default").
-- every gas particle outside the membrane: membrane:escaped's count beyond a
-- quarter cell plus its skin-grazers (issue 30: the count this file used)
local function outside(beyond, _, grazing) return beyond + grazing end
local dog = require("dogbone")
local h, t_end = 0.05, lamina.param("t_end", 4)

local function run(o)
  local sim, gas, mem = dog.setup(h, o)
  local rec = sim:record{ every = 0.01, values = {
    p = function() return gas:pressure(mem) end,
    hoop = function() return mem:hoop_stress() end,
    r0 = function() return mem:radius_at(0) end,
    r90 = function() return mem:radius_at(90) end,
    out = function() return outside(mem:escaped(gas)) end } }
  sim:run{ t_end = t_end }
  local t0 = t_end - 1
  local p, hoop = rec:mean("p", t0, t_end), rec:mean("hoop", t0, t_end)
  local r0, r90 = rec:mean("r0", t0, t_end), rec:mean("r90", t0, t_end)
  local out = 0
  for _, v in ipairs(rec:column("out")) do out = math.max(out, v) end
  local prt = p * 0.5 * (r0 + r90) / 0.1
  print(string.format("cell 0.05, %s, %s: r(0) %.4f r(90) %.4f p %.2f hoop %+.2f %% of p r / t, "
                      .. "gas outside (most at a sample) %d", sim.basis, o.force, r0, r90, p,
                      100 * (hoop / prt - 1), out))
  return r0, r90, p, hoop / prt - 1, out
end

local r0, r90, p, dh, out = run{ basis = "bspline2", force = "point", threads = 2 }
assert(out == 0, out .. " gas particles outside the membrane")
assert(math.abs(r0 - 1.394) < 0.034 and math.abs(r90 - 1.396) < 0.034,
       string.format("radii %.4f / %.4f, [T] Table 5 1.394 / 1.396", r0, r90))
assert(math.abs(p - 29.0) < 2.7, string.format("pressure %.2f, [T] Table 5 29.0", p))
assert(math.abs(dh) < 0.05, string.format("hoop %+.2f %% of p r / t", 100 * dh))

run{ basis = "bspline2", force = "segment", count = 90, threads = 2 }
