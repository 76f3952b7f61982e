-- title: The equations of one full time step, written out and run beside lamina's step
-- source: York's dissertation [T] §3.6, Table 9 (MPM equations for one full time step)
-- look: the steps of Table 9 in order, each with its equation, and for a
--   small spinning, stretching elastic block the largest difference between
--   what this page computes from those equations alone and lamina's own
--   step, per quantity, after each of two steps (the second with the
--   stresses the first made, so the internal force acts)
-- checks: the particles' positions, velocities, densities and stresses after
--   two steps against the equations of Table 9 computed here in Lua
--   (MUSL, the papers' scheme: [F] eqs 5-16): (1) m_i = sum_p m_p N_ip, p_i =
--   sum_p m_p v_p N_ip; (2) f_i = -sum_p V_p sigma_p G_ip; (3) p_i^L = p_i +
--   dt f_i; (4) v_p += dt sum_i N_ip f_i / m_i, x_p += dt sum_i N_ip p_i^L /
--   m_i; (5) the velocities mapped again, v_i = sum_p m_p v_p N_ip / m_i;
--   (6) the velocity gradient L_p = sum_i v_i G_ip, the density rho_p / (1 +
--   dt tr D) and the stress by the Jaumann rate with Hooke's law (plane
--   strain, [F] eqs 18-20); each to round-off (relative 1e-12)
--   Beside them ([T] Table 9's "Configuration" column, table9_configurations.png)
--   the grid and the points at the table's time levels 0, L1, regrid and 1,
--   drawn from this page's first step (displacements x25)
-- assumed: a 2 x 2 cell block of 4 points a cell (rho 1, E 100, nu 0.3) in
--   an otherwise empty 6 x 6 grid of unit cells, free sides, v = w x r plus
--   a stretch, dt = 0.01
-- thumb: diagram_time_step.png
local out = lamina.param("out", "out/diagram_time_step")

local dt, cx, cy, E, nu, rho0 = 0.01, 3, 3, 100, 0.3, 1
local function v0(x, y) return -(y - cy) + 0.2 * (x - cx), (x - cx) + 0.1 * (y - cy) end
local sim = lamina.sim{ basis = "linear", scheme = "musl", domain = {0, 0, 6, 6}, cell = 1, dt = dt,
                        boundary = { left = "free", right = "free", bottom = "free", top = "free" } }
local block = sim:body{ material = lamina.elastic{ rho = rho0, E = E, nu = nu, plane = "strain" }, ppc = 4,
                        name = "block", region = lamina.rect{ x0 = 2, y0 = 2, x1 = 4, y1 = 4 }, velocity = v0 }

-- the page's own state, from lamina's seeding
local P0 = block:particles()
local n = P0.n
local S = { x = {}, y = {}, vx = {}, vy = {}, m = {}, rho = {}, sxx = {}, syy = {}, sxy = {}, szz = {} }
for p = 1, n do
  S.x[p], S.y[p], S.vx[p], S.vy[p], S.m[p], S.rho[p] = P0.x[p], P0.y[p], P0.vx[p], P0.vy[p], P0.mass[p], P0.rho[p]
  S.sxx[p], S.syy[p], S.sxy[p], S.szz[p] = 0, 0, 0, 0
end
local G, lam = E / (2 * (1 + nu)), E * nu / ((1 + nu) * (1 - 2 * nu))

-- the linear basis on unit cells: (node i, node j, N, dN/dx, dN/dy)
local function basis(x, y)
  local i, j = math.floor(x), math.floor(y)
  local r, s = x - i, y - j
  return { {i, j, (1 - r) * (1 - s), -(1 - s), -(1 - r)}, {i + 1, j, r * (1 - s), 1 - s, -r},
           {i + 1, j + 1, r * s, s, r}, {i, j + 1, (1 - r) * s, -s, 1 - r} }
end
local function key(w) return w[1] + 7 * w[2] end

-- the first step's configurations, for Table 9's "Configuration" column
local snap

local function step()
  local B = {}
  for p = 1, n do B[p] = basis(S.x[p], S.y[p]) end
  -- (1) mass and momentum to the grid; (2) internal force
  local m, px, py, fx, fy = {}, {}, {}, {}, {}
  for p = 1, n do
    local V = S.m[p] / S.rho[p]
    for _, w in ipairs(B[p]) do
      local k = key(w)
      m[k] = (m[k] or 0) + S.m[p] * w[3]
      px[k], py[k] = (px[k] or 0) + S.m[p] * S.vx[p] * w[3], (py[k] or 0) + S.m[p] * S.vy[p] * w[3]
      fx[k] = (fx[k] or 0) - V * (S.sxx[p] * w[4] + S.sxy[p] * w[5])
      fy[k] = (fy[k] or 0) - V * (S.sxy[p] * w[4] + S.syy[p] * w[5])
    end
  end
  -- (3) the momentum equation on the grid
  local plx, ply = {}, {}
  for k in pairs(m) do plx[k], ply[k] = px[k] + dt * fx[k], py[k] + dt * fy[k] end
  if not snap then
    snap = { x0 = {}, y0 = {}, vL = {} }
    for p = 1, n do snap.x0[p], snap.y0[p] = S.x[p], S.y[p] end
    for k in pairs(m) do snap.vL[k] = { plx[k] / m[k], ply[k] / m[k] } end
  end
  -- (4) the particles' velocities and positions
  for p = 1, n do
    local ax, ay, ux, uy = 0, 0, 0, 0
    for _, w in ipairs(B[p]) do
      local k = key(w)
      ax, ay = ax + w[3] * fx[k] / m[k], ay + w[3] * fy[k] / m[k]
      ux, uy = ux + w[3] * plx[k] / m[k], uy + w[3] * ply[k] / m[k]
    end
    S.vx[p], S.vy[p] = S.vx[p] + dt * ax, S.vy[p] + dt * ay
    S.x[p], S.y[p] = S.x[p] + dt * ux, S.y[p] + dt * uy
  end
  if not snap.x1 then
    snap.x1, snap.y1 = {}, {}
    for p = 1, n do snap.x1[p], snap.y1[p] = S.x[p], S.y[p] end
  end
  -- (5) the velocities mapped again (MUSL), at the old weights
  local qx, qy = {}, {}
  for p = 1, n do
    for _, w in ipairs(B[p]) do
      local k = key(w)
      qx[k], qy[k] = (qx[k] or 0) + S.m[p] * S.vx[p] * w[3], (qy[k] or 0) + S.m[p] * S.vy[p] * w[3]
    end
  end
  -- (6) velocity gradient, density, stress (Jaumann rate, Hooke's law)
  for p = 1, n do
    local Lxx, Lxy, Lyx, Lyy = 0, 0, 0, 0
    for _, w in ipairs(B[p]) do
      local k = key(w)
      local ux, uy = qx[k] / m[k], qy[k] / m[k]
      Lxx, Lxy = Lxx + ux * w[4], Lxy + ux * w[5]
      Lyx, Lyy = Lyx + uy * w[4], Lyy + uy * w[5]
    end
    local dexx, deyy, dexy = dt * Lxx, dt * Lyy, 0.5 * dt * (Lxy + Lyx)
    local wsp = 0.5 * (Lxy - Lyx)
    S.rho[p] = S.rho[p] / (1 + dexx + deyy)
    local sx, sy, s = S.sxx[p], S.syy[p], S.sxy[p]
    S.sxx[p] = sx + 2 * wsp * s * dt + (lam + 2 * G) * dexx + lam * deyy
    S.syy[p] = sy - 2 * wsp * s * dt + lam * dexx + (lam + 2 * G) * deyy
    S.sxy[p] = s + wsp * (sy - sx) * dt + 2 * G * dexy
    S.szz[p] = S.szz[p] + lam * (dexx + deyy)
  end
end

local rows, worst_all = {}, 0
local scale = { x = 1, v = 1, rho = rho0, s = 0 }
for k = 1, 2 do
  step()
  sim:step()
  local P = block:particles()
  local dx, dv, dr, ds, smax = 0, 0, 0, 0, 0
  for p = 1, n do
    dx = math.max(dx, math.abs(P.x[p] - S.x[p]), math.abs(P.y[p] - S.y[p]))
    dv = math.max(dv, math.abs(P.vx[p] - S.vx[p]), math.abs(P.vy[p] - S.vy[p]))
    dr = math.max(dr, math.abs(P.rho[p] - S.rho[p]) / rho0)
    ds = math.max(ds, math.abs(P.sxx[p] - S.sxx[p]), math.abs(P.syy[p] - S.syy[p]),
                  math.abs(P.sxy[p] - S.sxy[p]), math.abs(P.szz[p] - S.szz[p]))
    smax = math.max(smax, math.abs(S.sxx[p]), math.abs(S.syy[p]), math.abs(S.sxy[p]))
  end
  ds = ds / smax
  rows[k] = { dx, dv, dr, ds, smax }
  worst_all = math.max(worst_all, dx, dv, dr, ds)
  print(string.format("step %d: positions %.2e, velocities %.2e, density %.2e (of rho0), stress %.2e "
    .. "(of its largest, %.3g)", k, dx, dv, dr, ds, smax))
end

local fig = lamina.figure{ width = 1100, height = 640, panels = {1, 1},
  title = "[T] Table 9: the MPM equations for one full time step (MUSL), and lamina's step beside them" }
fig:panel{ index = 1, window = {0, 0, 2.2, 1}, title = "computed from the equations in this page, against lamina's step",
           caption = string.format("a spinning, stretching elastic block, %d points; largest difference over two "
                                   .. "steps %.0e", n, worst_all) }
local lines = {
  "(1) to the grid:  m_i = sum_p m_p N_ip,   p_i = sum_p m_p v_p N_ip",
  "(2) internal force:  f_i = - sum_p V_p sigma_p . G_ip",
  "(3) momentum equation:  p_i^L = p_i + dt f_i",
  "(4) the points:  v_p += dt sum_i N_ip f_i / m_i,   x_p += dt sum_i N_ip p_i^L / m_i",
  "(5) remap (MUSL):  v_i = sum_p m_p v_p N_ip / m_i",
  "(6) strain rate L_p = sum_i v_i G_ip;  rho_p / (1 + dt tr D);  sigma by the Jaumann rate, Hooke's law",
}
local y = 0.93
for _, l in ipairs(lines) do
  fig:text{ text = l, at = {0.03, y} }
  y = y - 0.085
end
y = y - 0.05
local cols = { 0.95, 1.25, 1.55, 1.85 }
fig:text{ text = "largest difference, page against lamina:", at = {0.03, y} }
for c, h in ipairs{ "positions", "velocities", "density", "stress" } do
  fig:text{ text = h, at = {cols[c], y}, align = "center" }
end
for k = 1, 2 do
  y = y - 0.07
  fig:text{ text = string.format("after step %d", k), at = {0.03, y} }
  for c = 1, 4 do fig:text{ text = string.format("%.1e", rows[k][c]), at = {cols[c], y}, align = "center" } end
end
fig:write(out .. "/diagram_time_step.png")

-- [T] Table 9's "Configuration" column: the grid and the points at each time
-- level of the first step, from this page's own computation (the nodes'
-- v^L of (3), the points' moves of (4)); the step's displacements, about
-- 0.01 of a cell, drawn 25 times larger (the same factor on nodes and
-- points: each point stays at its place in its moved cell, eq (4) being
-- x_p + dt sum_i N_ip v_i^L)
local F = 25
local cfg = lamina.figure{ width = 1400, height = 470, panels = {4, 1},
  title = "[T] Table 9, the configurations: one step of the block, displacements drawn x25" }
local win = {1.4, 1.4, 4.6, 4.6}
local function pts(xs, ys, moved)
  local t = {}
  for p = 1, n do
    t[p] = moved and {snap.x0[p] + F * (xs[p] - snap.x0[p]), snap.y0[p] + F * (ys[p] - snap.y0[p])} or {xs[p], ys[p]}
  end
  return t
end
local nodes = {}
for k in pairs(snap.vL) do nodes[#nodes + 1] = {k % 7, k // 7} end
table.sort(nodes, function(a, b) return a[1] + 7 * a[2] < b[1] + 7 * b[2] end)
cfg:panel{ index = 1, window = win, title = "0: map the points to the grid",
           caption = "(1)-(2): m_i, p_i and f_i at the nodes (circles)" }
cfg:grid{ box = {1, 1, 5, 5}, cells = {4, 4} }
cfg:points{ points = nodes, style = "circle", size = 9, colour = "black" }
cfg:points{ points = pts(snap.x0, snap.y0), style = "dot", size = 7, colour = "computed" }
cfg:panel{ index = 2, window = win, title = "L1: Lagrangian step, the grid moves",
           caption = "(3)-(6): v^L at the nodes moves them, and the points with them" }
local function moved(i, j)
  local v = snap.vL[i + 7 * j]
  return v and {i + F * dt * v[1], j + F * dt * v[2]}
end
for _, nd in ipairs(nodes) do
  local here = moved(nd[1], nd[2])
  for _, nb in ipairs{ {nd[1] + 1, nd[2]}, {nd[1], nd[2] + 1} } do
    local there = moved(nb[1], nb[2])
    if there then cfg:polyline{ points = {here, there}, colour = "black", width = 1.5 } end
  end
end
local mv = {}
for _, nd in ipairs(nodes) do mv[#mv + 1] = moved(nd[1], nd[2]) end
cfg:points{ points = mv, style = "circle", size = 9, colour = "black" }
cfg:points{ points = pts(snap.x1, snap.y1, true), style = "dot", size = 7, colour = "computed" }
cfg:panel{ index = 3, window = win, title = "regrid: the grid returns",
           caption = "no equation: the points keep x_p, v_p, sigma_p (grey: where they were)" }
cfg:grid{ box = {1, 1, 5, 5}, cells = {4, 4} }
cfg:points{ points = pts(snap.x0, snap.y0), style = "circle", size = 7, colour = "grey" }
cfg:points{ points = pts(snap.x1, snap.y1, true), style = "dot", size = 7, colour = "computed" }
cfg:panel{ index = 4, window = win, title = "1: the next step maps them again",
           caption = "(1)-(2) from the new positions, on the fixed grid" }
cfg:grid{ box = {1, 1, 5, 5}, cells = {4, 4} }
cfg:points{ points = nodes, style = "circle", size = 9, colour = "black" }
cfg:points{ points = pts(snap.x1, snap.y1, true), style = "dot", size = 7, colour = "computed" }
cfg:write(out .. "/table9_configurations.png")

lamina.report{
  step_equations = { worst_all, ref = 0, tol = 1e-12,
    unit = "largest difference over two steps: positions, velocities, density / rho0, stress / its largest (Table 9's equations against lamina; round-off)" },
  stress_after_two_steps = { rows[2][5], unit = "largest stress component (the internal force acts in step 2)" },
  state_hash = sim:hash(),
}
