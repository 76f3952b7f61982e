-- pendulum_fem_mass.lua - is our bar FEM (assets/lua/barfem.lua, lumped
-- masses) a converged reference for membrane_pendulum_no_wrinkle's theta(t)?
-- The same pendulum ([T] §5.7.3, Table 1) on a consistent-mass bar FEM
-- (element mass rho A le / 6 [2 1; 1 2], the tridiagonal of the free nodes
-- solved each step, symplectic Euler at dt = safety le / (c sqrt 3): the
-- consistent mass's highest frequency is sqrt 3 higher), against the lumped
-- one at each element count; rms of theta over t <= 1.8 sampled every 2e-3
-- (docs/robustness.md "Why the pendulum is worse on the consistent mass":
-- at 80 elements the two are 1.1e-4 deg apart, at 10 each is within 6e-4
-- deg of the 80-element consistent run). Pure Lua: the 80-element runs
-- take minutes.
--   lamina run scripts/measure/pendulum_fem_mass.lua [--set counts="10 20"] [--set ref=80]
local counts = lamina.param("counts", "10 20")
local nref = tonumber(lamina.param("ref", "80"))
local barfem = require("barfem")
local E, L, m, g, th0, rho, A = 1e6, 0.73, 3.3, 20, 19.8, 0.1, 0.1
local px, py = 0.6, 1.0
local mx, my = px + L * math.sin(math.rad(th0)), py - L * math.cos(math.rad(th0))
local t_end, safety = 1.8, 0.9

local function consistent(n)
  local le, c = L / n, math.sqrt(E / rho)
  local dt, EA, me = safety * le / (c * math.sqrt(3)), E * A, rho * A * le
  local x, y, vx, vy = {}, {}, {}, {}
  for i = 0, n do
    x[i], y[i] = px + (mx - px) * i / n, py + (my - py) * i / n
    vx[i], vy[i] = 0, 0
  end
  -- rows of the free nodes 1..n: diagonal 4 me/6 (the last 2 me/6 + m),
  -- off-diagonal me/6; node 0 is the pivot
  local diag, off = {}, me / 6
  for i = 1, n do diag[i] = i == n and 2 * me / 6 + m or 4 * me / 6 end
  local function solve(f)   -- Thomas algorithm
    local cp, dp, a = {}, {}, {}
    cp[1], dp[1] = off / diag[1], f[1] / diag[1]
    for i = 2, n do
      local den = diag[i] - off * cp[i - 1]
      cp[i], dp[i] = off / den, (f[i] - off * dp[i - 1]) / den
    end
    a[n] = dp[n]
    for i = n - 1, 1, -1 do a[i] = dp[i] - cp[i] * a[i + 1] end
    return a
  end
  local out, fx, fy = { t = {}, theta = {} }, {}, {}
  local next_t, t, k = 0, 0, 0
  while t <= t_end + 0.5 * dt do
    if t >= next_t - 0.5 * dt then
      out.t[#out.t + 1] = t
      out.theta[#out.theta + 1] = math.deg(math.atan(x[n] - x[0], -(y[n] - y[0])))
      next_t = next_t + 1e-3
    end
    -- gravity's consistent load on a uniform field is the lumped one
    for i = 1, n do fx[i], fy[i] = 0, -g * (i == n and me / 2 + m or me) end
    for e = 0, n - 1 do
      local dx, dy = x[e + 1] - x[e], y[e + 1] - y[e]
      local l = math.sqrt(dx * dx + dy * dy)
      local T = EA * (l - le) / le
      if e > 0 then fx[e], fy[e] = fx[e] + T * dx / l, fy[e] + T * dy / l end
      fx[e + 1], fy[e + 1] = fx[e + 1] - T * dx / l, fy[e + 1] - T * dy / l
    end
    local ax, ay = solve(fx), solve(fy)
    for i = 1, n do
      vx[i], vy[i] = vx[i] + dt * ax[i], vy[i] + dt * ay[i]
      x[i], y[i] = x[i] + dt * vx[i], y[i] + dt * vy[i]
    end
    k = k + 1
    t = k * dt
  end
  return out
end

local function lumped(n)
  return barfem.run{ from = {px, py}, to = {mx, my}, elements = n, rho = rho, A = A, E = E,
                     end_mass = m, g = {0, -g}, one_way = false, t_end = t_end, every = 1e-3,
                     safety = safety }
end

local function rms(a, b)
  local se, k = 0, 0
  for i = 1, #a.t, 2 do
    se = se + (a.theta[i] - barfem.at(b.t, b.theta, a.t[i]))^2
    k = k + 1
  end
  return math.sqrt(se / k)
end

local ref = consistent(nref)
print(string.format("elements  lumped vs consistent %d   consistent vs consistent %d  (rms theta, deg)", nref, nref))
print(string.format("%8d  %.2e                  (lumped %d vs consistent %d)", nref, rms(lumped(nref), ref), nref, nref))
for w in counts:gmatch("%d+") do
  local n = tonumber(w)
  print(string.format("%8d  %.2e                  %.2e", n, rms(lumped(n), ref), rms(consistent(n), ref)))
end
