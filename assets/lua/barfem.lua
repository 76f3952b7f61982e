-- barfem.lua - an explicit bar-element finite element solution for strings:
-- the independent reference of the pendulum ([M] §3.1.2: "a simulation
-- performed with an explicit finite element method using bar elements is
-- used for comparison", Fig 11) and of the spring-mass problems.
--
-- Nodes 0..n along a straight initial string; node 0 is pinned; lumped
-- masses rho*A*le (half at the ends) plus the end mass on the last node;
-- each bar carries the tension EA*eps with eps = (l - l0)/l0 (none in
-- compression when one_way is set: [M] §3.2, Fig 13); gravity on every
-- node; symplectic Euler (v += dt F/m, x += dt v) at dt = safety*le/c.
--
-- barfem.run{ from = {x, y}, to = {x, y}, elements = 20, rho =, A =, E =,
--             end_mass =, g = {gx, gy}, one_way = false, t_end =,
--             every =, safety = 0.5, initial_strain = f(u) or nil,
--             snapshots = {t1, t2, ...} or nil }
-- returns { t = {...}, theta = {...}, x = {...}, y = {...} } sampled every
-- `every`: theta in degrees from the downward vertical (first -> last
-- node), x, y of the last node; with `snapshots`, also snaps = { {t =, x =
-- {...}, y = {...}}, ... }: every node's position at the first step at or
-- after each of those times ([M] Fig 11 draws them).
local M = {}

function M.run(o)
  local n = o.elements or 20
  local x0, y0, x1, y1 = o.from[1], o.from[2], o.to[1], o.to[2]
  local Ltot = math.sqrt((x1 - x0)^2 + (y1 - y0)^2)
  local le = Ltot / n
  local c = math.sqrt(o.E / o.rho)
  local dt = (o.safety or 0.5) * le / c
  local EA = o.E * o.A
  local gx, gy = o.g[1], o.g[2]
  local x, y, vx, vy, m, l0 = {}, {}, {}, {}, {}, {}
  for i = 0, n do
    x[i] = x0 + (x1 - x0) * i / n
    y[i] = y0 + (y1 - y0) * i / n
    vx[i], vy[i] = 0, 0
    m[i] = o.rho * o.A * le * ((i == 0 or i == n) and 0.5 or 1)
  end
  m[n] = m[n] + (o.end_mass or 0)
  for e = 0, n - 1 do
    -- rest length: a negative initial strain is slack, l0 = l / (1 + eps)
    local eps = o.initial_strain and o.initial_strain((e + 0.5) / n) or 0
    l0[e] = le / (1 + eps)
  end
  local fx, fy = {}, {}
  local out = { t = {}, theta = {}, x = {}, y = {}, snaps = {} }
  local snap_at = o.snapshots or {}
  local every = o.every or 1e-3
  local next_t, t, k = 0, 0, 0
  local function sample()
    out.t[#out.t + 1] = t
    out.theta[#out.theta + 1] = math.deg(math.atan(x[n] - x[0], -(y[n] - y[0])))
    out.x[#out.x + 1], out.y[#out.y + 1] = x[n], y[n]
  end
  while t <= o.t_end + 0.5 * dt do
    if t >= next_t - 0.5 * dt then
      sample()
      next_t = next_t + every
    end
    local s = snap_at[#out.snaps + 1]
    if s and t >= s - 0.5 * dt then
      local sx, sy = {}, {}
      for i = 0, n do sx[i + 1], sy[i + 1] = x[i], y[i] end
      out.snaps[#out.snaps + 1] = { t = t, x = sx, y = sy }
    end
    for i = 0, n do fx[i], fy[i] = m[i] * gx, m[i] * gy end
    for e = 0, n - 1 do
      local dx, dy = x[e + 1] - x[e], y[e + 1] - y[e]
      local l = math.sqrt(dx * dx + dy * dy)
      local eps = (l - l0[e]) / l0[e]
      local T = (o.one_way and eps < 0) and 0 or EA * eps
      local ux, uy = T * dx / l, T * dy / l
      fx[e], fy[e] = fx[e] + ux, fy[e] + uy
      fx[e + 1], fy[e + 1] = fx[e + 1] - ux, fy[e + 1] - uy
    end
    for i = 1, n do
      vx[i] = vx[i] + dt * fx[i] / m[i]
      vy[i] = vy[i] + dt * fy[i] / m[i]
      x[i] = x[i] + dt * vx[i]
      y[i] = y[i] + dt * vy[i]
    end
    k = k + 1
    t = k * dt
  end
  out.dt = dt
  return out
end

-- Linear interpolation of a sampled series (ts ascending) at time t.
function M.at(ts, vs, t)
  if t <= ts[1] then return vs[1] end
  local lo, hi = 1, #ts
  if t >= ts[hi] then return vs[hi] end
  while hi - lo > 1 do
    local mid = (lo + hi) // 2
    if ts[mid] <= t then lo = mid else hi = mid end
  end
  local f = (t - ts[lo]) / (ts[hi] - ts[lo])
  return vs[lo] + f * (vs[hi] - vs[lo])
end

return M
