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
local h = 1 / 32
local g = -10
local sim = lamina.sim{domain = {0, 0, 1.5, 1.0}, cell = h, dt = 2e-4, gravity = {0, g},
                       boundary = "free", mass = "corrected"}
local wire = lamina.membrane{rho = 100, E = 5e4, nu = 0, thickness = 0.01, law = "uniaxial"}
local s = sim:membrane{material = wire, curve = lamina.segment{from = {0.25, 0.51}, to = {1.25, 0.51}},
                       spacing = h / 2, initial_strain = 0.01, name = "string"}
local function v_left(t) return 0.02 * math.cos(7 * t), 0.05 * math.sin(9 * t) end
local left = s:pin{points = {1}, velocity = v_left}
local right = s:pin{points = {#s}}
local function momentum(body)
  local q = body:particles()
  local px, py, m = 0, 0, 0
  for i = 1, #q.x do
    px, py, m = px + q.mass[i] * q.vx[i], py + q.mass[i] * q.vy[i], m + q.mass[i]
  end
  return px, py, m
end
local p0 = s:particles()
local xl, yl, xr, yr = p0.x[1], p0.y[1], p0.x[#p0.x], p0.y[#p0.y]
local worst, largest = 0, 0
for _ = 1, 2000 do
  local ax, ay, m = momentum(s)
  local vx, vy = v_left(sim.t + sim.dt / 2)
  xl, yl = xl + sim.dt * vx, yl + sim.dt * vy
  sim:step(1)
  local bx, by = momentum(s)
  local r1x, r1y = left:reaction()
  local r2x, r2y = right:reaction()
  local fx, fy = r1x + r2x, r1y + r2y + m * g
  worst = math.max(worst, math.abs((bx - ax) / sim.dt - fx), math.abs((by - ay) / sim.dt - fy))
  largest = math.max(largest, math.abs(r1x), math.abs(r1y), math.abs(r2x), math.abs(r2y))
end
local q = s:particles()
print(string.format("corrected mass: momentum balance off by %.3e of the largest reaction %.4g; driven end off by %.2e, %.2e; held end moved %.2e, %.2e",
                    worst / largest, largest, q.x[1] - xl, q.y[1] - yl, q.x[#q.x] - xr, q.y[#q.y] - yr))
assert(worst < 1e-9 * largest, "the reactions do not balance the string's momentum change")
assert(math.abs(q.x[1] - xl) < 1e-12 and math.abs(q.y[1] - yl) < 1e-12, "the driven end did not follow its pin")
assert(q.x[#q.x] == xr and q.y[#q.y] == yr, "the held end moved")
