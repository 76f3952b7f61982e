-- Issue 30 item 3: what a pin's reaction means once a pin holds only its
-- point (src/mpm/pin.c, src/mpm/constraint.c). The force a pin exerts on
-- the material is what changes the material's momentum: over every step,
-- sum m v over the body's points changes by (sum of reactions + weight) dt.
-- (1) A string (L = 1, T = 5 as tests/verify's strings, cell 1/32, points
-- half a cell apart, off the node lines) under gravity 10, held at rest at
-- its right end and driven at its left end at (0.02 cos 7t, 0.05 sin 9t),
-- 2000 steps: both pins hold their points (no node shared). Exact: the
-- balance to rounding; measured 1.3e-13 of the largest force (with the
-- momentum solve's impulse counted in the reaction it was off by 32 %).
-- The driven point moves by dt v_pin a step exactly (the sum of its
-- velocities at the steps' middles, t + dt/2, as docs/api.md says), the
-- held one not at all.
-- (2) A block (1 x 1, rho 1000, E 1e6, cell 0.02, 4 points a cell) under
-- gravity whose top 0.1 (1000 points, packed closer than a stencil) is
-- pinned: such a pin holds its nodes (the constraint's system is singular
-- there: measured 55 s for 200 steps, the Gauss-Seidel sweeps spent, and
-- the energy grew 55 %). Exact: the total energy never rises above its
-- start (the pin, at rest, does no work; asserted to 1e-9 of the block's
-- weight times a unit height). The momentum balance is printed, not
-- asserted: a pin that holds nodes resets its points' velocities outside
-- its reaction (measured 3.1e-3 of the weight).
local g = -10
local pinned_string = require("pinned_string")
local momentum = pinned_string.momentum
local worst, largest, dlx, dly, drx, dry, sim = pinned_string.balance()
print(string.format("string: momentum balance off by %.3e of the largest reaction %.4g; driven end off by %.2e, %.2e",
                    worst / largest, largest, dlx, dly))
assert(worst < 1e-9 * largest, "the reactions do not balance the string's momentum change")
assert(math.abs(dlx) < 1e-12 and math.abs(dly) < 1e-12, "the driven end did not follow its pin")
assert(drx == 0 and dry == 0, "the held end moved")
assert(sim:energy().kinetic > 0, "the string did not move")

local sim2 = lamina.sim{domain = {0, 0, 1.2, 1.2}, cell = 0.02, dt = 2e-5, gravity = {0, g}, boundary = "free"}
local block = sim2:body{material = lamina.elastic{rho = 1000, E = 1e6, nu = 0.3}, ppc = 4, name = "block",
                        region = lamina.rect{x0 = 0.1, y0 = 0.1, x1 = 1.1, y1 = 1.1}}
local lid = block:pin{points = function(_, y) return y > 1.0 end}
local e0 = sim2:energy().total
local emax, worst2, largest2 = e0, 0, 0
for _ = 1, 200 do
  local ax, ay, m = momentum(block)
  sim2:step(1)
  local bx, by = momentum(block)
  local rx, ry = lid:reaction()
  worst2 = math.max(worst2, math.abs((bx - ax) / sim2.dt - rx), math.abs((by - ay) / sim2.dt - ry - m * g))
  largest2 = math.max(largest2, math.abs(rx), math.abs(ry), math.abs(m * g))
  emax = math.max(emax, sim2:energy().total)
end
local _, _, mass = momentum(block)
local scale = mass * math.abs(g) * 1.0
print(string.format("block, %d points pinned: energy max %+.3e of m g (1 m) over its start, "
                    .. "momentum balance off by %.3e of %.4g", #lid, (emax - e0) / scale,
                    worst2 / largest2, largest2))
assert(#lid == 1000, "the lid holds " .. #lid .. " points")
assert(emax <= e0 + 1e-9 * scale, "the pinned block's energy rose")
assert(sim2:energy().kinetic > 0, "the block did not move")
