-- lamina.analysis.crossing and .gas_sides (issue 35 item 3) against exact
-- answers: a straight membrane y = 0.3 + 0.4 x crossed by vertical lines
-- (the height at x is known), a closed ring crossed through its centre,
-- and a gas block split by the straight membrane, a V-shaped one and the
-- ring, counted here point by point from the gas's own positions.
local A = lamina.analysis
local sim = lamina.sim{basis = "linear", domain = {0, 0, 1, 1}, cell = 0.1, dt = 1e-4}
local skin = lamina.membrane{rho = 1, E = 1e4, thickness = 0.01}
local line = function(x) return 0.3 + 0.4 * x end
local straight = sim:membrane{material = skin, count = 13, name = "straight",
                              curve = lamina.segment{from = {0.05, line(0.05)},
                                                     to = {0.95, line(0.95)}}}
local vee = sim:membrane{material = skin, count = 19, name = "vee",
                         curve = lamina.polyline{{0.05, 0.8}, {0.5, 0.2}, {0.95, 0.8}}}
local ring = sim:membrane{material = skin, count = 36, name = "ring",
                          curve = lamina.arc{center = {0.5, 0.5}, radius = 0.25}}
local air = lamina.gas{rho = 1, p = 1000}
local gas = sim:body{material = air, ppc = 4, name = "gas",
                     region = lamina.rect{x0 = 0.1, y0 = 0.1, x1 = 0.9, y1 = 0.9}}

local function near(name, got, want, tol)
  print(string.format("%-40s %.15g (exact %.15g)", name, got, want))
  assert(math.abs(got - want) <= tol, name .. ": " .. got .. " vs " .. want)
end

-- the straight membrane's height at x, at a point between its points and
-- at one of them (x = 0.05 + 0.075 k: k = 6 is x = 0.5)
for _, x in ipairs{0.5, 0.2, 0.77, 0.05} do
  local cx, cy, s, n = A.crossing(straight, {x, 0}, {x, 1})
  near(string.format("straight: height at x = %g", x), cy, line(x), 1e-15)
  near(string.format("straight: x of it at x = %g", x), cx, x, 1e-15)
  near(string.format("straight: distance from p0 at x = %g", x), s, line(x), 1e-15)
  assert(n == 1, "straight: " .. n .. " crossings at x = " .. x .. ", 1 expected")
end
-- from above: the distance is from p0
local _, cy, s = A.crossing(straight, {0.5, 1}, {0.5, 0})
near("straight: from above, distance", s, 1 - line(0.5), 1e-15)
near("straight: from above, height", cy, line(0.5), 1e-15)
-- none: beyond its end, or a line along it
local none, why = A.crossing(straight, {0.99, 0}, {0.99, 1})
assert(none == nil and why:find("does not cross"), tostring(why))
assert(A.crossing(straight, {0, line(0) + 0.1}, {1, line(1) + 0.1}) == nil,
       "a parallel line 0.1 above crosses it")
-- the ring through its centre: twice, the nearest at radius 0.25 (a point
-- of the ring lies on the horizontal through the centre)
local x, y, d, n = A.crossing(ring, {0, 0.5}, {1, 0.5})
assert(n == 2, "ring: " .. n .. " crossings, 2 expected")
near("ring: nearest crossing x", x, 0.25, 1e-15)
near("ring: its distance from p0", d, 0.25, 1e-15)
near("ring: its y", y, 0.5, 1e-15)
-- the V: two crossings of the horizontal y = 0.5, at x = 0.5 -+ 0.225
x, y, d, n = A.crossing(vee, {0, 0.5}, {1, 0.5})
assert(n == 2, "vee: " .. n .. " crossings")
near("vee: nearest crossing x", x, 0.275, 1e-14)

-- the gas on each side, counted here from its positions
local q = gas:particles()
local above_line, above_vee, outside_ring = 0, 0, 0
for i = 1, q.n do
  if q.y[i] > line(q.x[i]) then above_line = above_line + 1 end
  local v = math.max(0.8 - (q.x[i] - 0.05) * 0.6 / 0.45, 0.2 + (q.x[i] - 0.5) * 0.6 / 0.45)
  if q.y[i] > v then above_vee = above_vee + 1 end
  if (q.x[i] - 0.5) ^ 2 + (q.y[i] - 0.5) ^ 2 > 0.25 ^ 2 then outside_ring = outside_ring + 1 end
end
local plus, minus, on = A.gas_sides(gas, straight)
print(string.format("straight: %d above (left), %d below of %d (counted here: %d above)",
                    plus, minus, q.n, above_line))
assert(plus == above_line and minus == q.n - above_line and on == 0, "straight: sides differ")
plus, minus, on = A.gas_sides(gas, vee)
print(string.format("vee: %d above (left), %d below (counted here: %d above)", plus, minus,
                    above_vee))
assert(plus == above_vee and minus == q.n - above_vee and on == 0, "vee: sides differ")
-- the ring runs anticlockwise: its left is inside the polygon of its
-- chords, counted here by ray casting over the ring's own points
plus, minus, on = A.gas_sides(gas, ring)
local rp = ring:particles()
local inside = 0
for i = 1, q.n do
  local c = false
  for k = 1, rp.n do
    local j = k % rp.n + 1
    local xk, yk, xj, yj = rp.x[k], rp.y[k], rp.x[j], rp.y[j]
    if (yk > q.y[i]) ~= (yj > q.y[i]) and
       q.x[i] < xk + (q.y[i] - yk) * (xj - xk) / (yj - yk) then c = not c end
  end
  if c then inside = inside + 1 end
end
print(string.format("ring: %d inside (left), %d outside (counted here: %d inside)", plus, minus,
                    inside))
assert(plus == inside and minus == q.n - inside and on == 0, "ring: sides differ")

local function refuses(pattern, ...)
  local ok, err = pcall(...)
  assert(not ok and tostring(err):find(pattern), "expected /" .. pattern .. "/, got " .. tostring(err))
end
refuses("argument 1 must be a membrane", A.crossing, gas, {0, 0}, {1, 1})
refuses("argument 2 must be a membrane", A.gas_sides, gas, gas)
refuses("the body is the membrane itself", A.gas_sides, straight, straight)
refuses("p0 and p1 are the same point", A.crossing, straight, {0.5, 0}, {0.5, 0})
refuses("p1%[2%] is not a finite number", A.crossing, straight, {0.5, 0}, {0.5, 0 / 0})
refuses("p0 must be a point", A.crossing, straight, 0.5, {0.5, 1})
print("analysis membrane_sides: all checks passed")
