-- pinned_string.lua - a string held by two pins, one at rest and one driven,
-- and the momentum balance its pins' reactions must close (issue 30 item 3;
-- tests/physics/pin_momentum.lua and pin_momentum_corrected.lua).
--
-- The string: L = 1, T = 5 (as tests/verify's strings), cell 1/32, points
-- half a cell apart and off the node lines, gravity 10; its right end held
-- at rest, its left driven at (0.02 cos 7t, 0.05 sin 9t). Over every step
-- sum m v over its points changes by (sum of reactions + weight) dt.
local M = {}

-- sum m v and sum m over a body's points
function M.momentum(body)
  local q = body:particles()
  local px, py, m = 0, 0, 0
  for i = 1, #q.x do
    px, py, m = px + q.mass[i] * q.vx[i], py + q.mass[i] * q.vy[i], m + q.mass[i]
  end
  return px, py, m
end

-- Runs `steps` steps (2000 if nil) with the sim's extra settings `opts`
-- (e.g. {mass = "corrected"}); returns the worst imbalance, the largest
-- reaction, the driven end's offset from its pin's path (dx, dy), the held
-- end's movement (dx, dy) and the sim.
function M.balance(opts, steps)
  local h, g = 1 / 32, -10
  local def = {domain = {0, 0, 1.5, 1.0}, cell = h, dt = 2e-4, gravity = {0, g}, boundary = "free"}
  for k, v in pairs(opts or {}) do def[k] = v end
  local sim = lamina.sim(def)
  local wire = lamina.membrane{rho = 100, E = 5e4, nu = 0, thickness = 0.01, law = "uniaxial"}
  local s = sim:membrane{material = wire, curve = lamina.segment{from = {0.25, 0.51}, to = {1.25, 0.51}},
                         spacing = h / 2, initial_strain = 0.01, name = "string"}
  local function v_left(t) return 0.02 * math.cos(7 * t), 0.05 * math.sin(9 * t) end
  local left = s:pin{points = {1}, velocity = v_left}
  local right = s:pin{points = {#s}}
  local p0 = s:particles()
  local xl, yl, xr, yr = p0.x[1], p0.y[1], p0.x[#p0.x], p0.y[#p0.y]
  local worst, largest = 0, 0
  for _ = 1, steps or 2000 do
    local ax, ay, m = M.momentum(s)
    local vx, vy = v_left(sim.t + sim.dt / 2)
    xl, yl = xl + sim.dt * vx, yl + sim.dt * vy
    sim:step(1)
    local bx, by = M.momentum(s)
    local r1x, r1y = left:reaction()
    local r2x, r2y = right:reaction()
    local fx, fy = r1x + r2x, r1y + r2y + m * g
    worst = math.max(worst, math.abs((bx - ax) / sim.dt - fx), math.abs((by - ay) / sim.dt - fy))
    largest = math.max(largest, math.abs(r1x), math.abs(r1y), math.abs(r2x), math.abs(r2y))
  end
  local q = s:particles()
  return worst, largest, q.x[1] - xl, q.y[1] - yl, q.x[#q.x] - xr, q.y[#q.y] - yr, sim
end

return M
