-- V7 dog-bone membrane expansion ([F] §4.3, Tables III-IV; [T] §6.2,
-- Table 5; docs/physics.md V7), reduced: cells 0.4 / 0.2 / 0.1 to t = 2.5
-- (the gallery adds 0.05 and runs to t = 4). The construction of the shape
-- (not given numerically in the papers) is in assets/lua/dogbone.lua;
-- scripts/paper/gas_dogbone_superellipse.lua says why (the V7 reference page,
-- scripts/paper/gas_dogbone.lua, now runs [T] Box 9: assets/lua/dogbone_box9.lua).
-- Checks (issue 8): gas contained at every refinement; at cell 0.1 the
-- final shape is circular (radius at 0 and 90 degrees within 1 %) and the
-- time-averaged hoop stress within 5 % of p r / t; final radius and
-- pressure converge with refinement (the radius grows towards the taut
-- radius 1.40 and the steps shrink, the pressure falls towards the energy
-- balance's 29.0 and the steps shrink).
-- p is the mean over the space the membrane encloses, gas:pressure(mem) =
-- sum V_p p_p / A: the pressure integral the internal forces use, over the
-- polygon's area. Measured to t = 2.5 (mean over [1.5, 2.5]): p 32.33 /
-- 29.78 / 29.48, hoop -7.5 / -4.3 / -2.5 % from p r / t. The mean over the
-- particles (gamma - 1) rho_p e_p is printed beside it, not asserted:
-- rho_p from the continuity update drifts from the particles' spacing
-- (sum m / rho is 21 % above the enclosed area at t = 4, cell 0.1), and
-- against it the hoop stress is -22 / -11 / +1.3 % off (docs/decisions.md
-- "Gas pressure over the space").
-- Energy ([F] §4.3.1: "less energy dissipation" with refinement): the
-- loss is measured on the energy the dynamics sees, with the kinetic
-- energy of the particles' momentum mapped to the grid
-- (sim:energy().grid_kinetic). The particles' own sum 1/2 m v^2 also holds
-- FLIP's hidden velocity, which the grid cannot see and which moves
-- nothing; both are printed. Measured to t = 2.5: visible loss 9.4 / 4.6 /
-- 1.4 %, hidden kinetic energy at the end 11.0 / 6.3 / 2.9 (of ~112), both
-- falling with refinement; the particle total rises by 0.5 / 1.0 / 1.2 %
-- (the hidden energy outweighs the loss), reported, not asserted.
-- every gas particle outside the membrane: membrane:escaped's count beyond a
-- quarter cell plus its skin-grazers (issue 30: the count this file used)
local function outside(beyond, _, grazing) return beyond + grazing end
local dog = require("dogbone")
local t_end = 2.5

local function expand(h)
  local sim, gas, mem = dog.setup(h)
  local escaped = 0
  local rec = sim:record{ every = 0.01, energy = true, values = {
    p = function() return gas:pressure(mem) end,
    pp = function() return gas:pressure("particles") end,
    hoop = function() return mem:hoop_stress() end,
    r0 = function() return mem:radius_at(0) end,
    r90 = function() return mem:radius_at(90) end,
    gk = function() return sim:energy().grid_kinetic end,
    escaped = function() escaped = math.max(escaped, outside(mem:escaped(gas))); return escaped end } }
  sim:run{ t_end = t_end }
  local t0 = t_end - 1
  local r = { p = rec:mean("p", t0, t_end), pp = rec:mean("pp", t0, t_end), hoop = rec:mean("hoop", t0, t_end),
              r0 = rec:mean("r0", t0, t_end), r90 = rec:mean("r90", t0, t_end), escaped = escaped }
  local tot, ke, gk = rec:column("total"), rec:column("kinetic"), rec:column("gk")
  local n = #tot
  local vis0, vis1 = tot[1] - ke[1] + gk[1], tot[n] - ke[n] + gk[n]
  r.dE = (tot[n] - tot[1]) / tot[1]
  r.loss = (vis0 - vis1) / vis0
  r.hidden = ke[n] - gk[n]
  r.r = 0.5 * (r.r0 + r.r90)
  r.prt = r.p * r.r / 0.1
  r.pprt = r.pp * r.r / 0.1
  print(string.format("V7 cell %.2f: r(0) %.4f r(90) %.4f p %.2f hoop %.1f vs p r / t %.1f "
    .. "(%+.1f %%; particle mean p %.2f: %+.1f %%), gas outside %d, visible energy loss %.2f %%, hidden kinetic energy %.2f, "
    .. "particle energy %+.2f %%", h, r.r0, r.r90, r.p, r.hoop, r.prt,
    100 * (r.hoop - r.prt) / r.prt, r.pp, 100 * (r.hoop - r.pprt) / r.pprt, escaped, 100 * r.loss, r.hidden, 100 * r.dE))
  return r
end

local a, b, c = expand(0.4), expand(0.2), expand(0.1)
for _, r in ipairs{a, b, c} do assert(r.escaped == 0, "gas escaped the membrane") end
assert(math.abs(c.r0 - c.r90) / c.r0 <= 0.01, "cell 0.1: not circular")
assert(math.abs(c.hoop - c.prt) / c.prt <= 0.05, "cell 0.1: hoop stress not within 5 % of p r / t")
assert(a.r < b.r and b.r < c.r and c.r - b.r < b.r - a.r, "radius not converging")
assert(a.p > b.p and b.p > c.p and b.p - c.p < a.p - b.p, "pressure not converging")
assert(a.loss > b.loss and b.loss > c.loss and c.loss > 0,
       "visible energy loss does not fall with refinement")
assert(a.hidden > b.hidden and b.hidden > c.hidden, "hidden kinetic energy does not fall with refinement")
print(string.format("reported: the particles' total energy changes by %+.2f / %+.2f / %+.2f %% "
  .. "(visible loss plus hidden FLIP kinetic energy)", 100 * a.dE, 100 * b.dE, 100 * c.dE))
