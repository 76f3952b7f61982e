-- title: Material point convection: the grid moves with the material for one step, then is reset
-- source: York's dissertation [T] §3.3, Fig 9 (eqs 3.20-3.21)
-- look: (a) material points in their cells at the start of a step; (b) the
--   updated Lagrangian step: every grid node moved by its velocity times
--   the step (eq 3.20's temporary velocity), the cells deformed with the
--   material and each point carried at the same place in its deformed cell
--   ("since the grid uses isoparametric elements the shape function values
--   at the new time level are the same as the previous time level"); (c)
--   the grid reset to its original place (the regrid), the points where the
--   step left them
-- checks: lamina's positions after one step against the isoparametric
--   update the text describes, computed here from the step's nodal
--   velocities: x_p' = sum_i N_i(x_p) (x_i + dt v_i) with v_i = sum_p m_p v_p
--   N_ip / sum_p m_p N_ip ([T] eqs 3.20-3.21; the block is unstressed, so the
--   step adds no force and the nodes' velocities are the mapped ones), to
--   round-off
-- assumed: a 2 x 2 cell block of 4 points a cell, spinning (v = w x r, w =
--   1) with a slight stretch, in an otherwise empty 6 x 6 grid of unit
--   cells; dt = 0.25, so that the cells' motion shows; E tiny so the step
--   is stable at that dt
-- thumb: diagram_convection.png
local out = lamina.param("out", "out/diagram_convection")

local dt, cx, cy = 0.25, 3, 3
local sim = lamina.sim{ basis = "linear", scheme = "musl", domain = {0, 0, 6, 6}, cell = 1, dt = dt,
                        boundary = { left = "free", right = "free", bottom = "free", top = "free" } }
local block = sim:body{ material = lamina.elastic{ rho = 1, E = 1e-6, nu = 0 }, ppc = 4, name = "block",
                        region = lamina.rect{ x0 = 2, y0 = 2, x1 = 4, y1 = 4 },
                        velocity = function(x, y) return -(y - cy) + 0.2 * (x - cx), (x - cx) + 0.1 * (y - cy) end }
local P0 = block:particles()
local x0, y0, m, vx, vy = {}, {}, {}, {}, {}
for i = 1, P0.n do x0[i], y0[i], m[i], vx[i], vy[i] = P0.x[i], P0.y[i], P0.mass[i], P0.vx[i], P0.vy[i] end

-- the nodes' velocities, eq 3.20's, by the mapping of [T] eqs 3.15-3.16
local function weights(x, y)
  local i, j = math.floor(x), math.floor(y)
  local r, s = x - i, y - j
  return { {i, j, (1 - r) * (1 - s)}, {i + 1, j, r * (1 - s)}, {i + 1, j + 1, r * s}, {i, j + 1, (1 - r) * s} }
end
local M, PX, PY = {}, {}, {}
for p = 1, #x0 do
  for _, w in ipairs(weights(x0[p], y0[p])) do
    local k = w[1] + 7 * w[2]
    M[k] = (M[k] or 0) + m[p] * w[3]
    PX[k], PY[k] = (PX[k] or 0) + m[p] * vx[p] * w[3], (PY[k] or 0) + m[p] * vy[p] * w[3]
  end
end
local function node_v(k) return PX[k] / M[k], PY[k] / M[k] end
-- eq 3.21 as the text reads it: each point at the same place in its moved cell
local xe, ye = {}, {}
for p = 1, #x0 do
  xe[p], ye[p] = 0, 0
  for _, w in ipairs(weights(x0[p], y0[p])) do
    local k = w[1] + 7 * w[2]
    local ux, uy = node_v(k)
    xe[p] = xe[p] + w[3] * (w[1] + dt * ux)
    ye[p] = ye[p] + w[3] * (w[2] + dt * uy)
  end
end

sim:step()
local P1 = block:particles()
local worst = 0
for p = 1, P1.n do worst = math.max(worst, math.abs(P1.x[p] - xe[p]), math.abs(P1.y[p] - ye[p])) end

local fig = lamina.figure{ width = 1200, height = 470, panels = {3, 1},
  title = "[T] Fig 9: material point convection, one step" }
local win = {1.4, 1.4, 4.6, 4.6}
local function pts_of(xs, ys)
  local t = {}
  for i = 1, #xs do t[i] = {xs[i], ys[i]} end
  return t
end
fig:panel{ index = 1, window = win, title = "(a) the start of the step" }
fig:grid{ box = {1, 1, 5, 5}, cells = {4, 4} }
fig:points{ points = pts_of(x0, y0), style = "dot", size = 8, colour = "computed" }
fig:panel{ index = 2, window = win, title = "(b) the grid moves with the material",
           caption = string.format("points at the same (r, s) in their moved cells: lamina's step to %.0e", worst) }
for j = 2, 4 do
  for i = 2, 4 do
    local k = i + 7 * j
    if M[k] then
      local ux, uy = node_v(k)
      local here = {i + dt * ux, j + dt * uy}
      for _, nb in ipairs{ {i + 1, j}, {i, j + 1} } do
        local kk = nb[1] + 7 * nb[2]
        if M[kk] and nb[1] <= 4 and nb[2] <= 4 then
          local vx2, vy2 = node_v(kk)
          fig:polyline{ points = {here, {nb[1] + dt * vx2, nb[2] + dt * vy2}}, colour = "black", width = 1.5 }
        end
      end
    end
  end
end
fig:points{ points = pts_of(P1.x, P1.y), style = "dot", size = 8, colour = "computed" }
fig:panel{ index = 3, window = win, title = "(c) the grid reset, the points moved" }
fig:grid{ box = {1, 1, 5, 5}, cells = {4, 4} }
fig:points{ points = pts_of(x0, y0), style = "circle", size = 7, colour = "grey" }
fig:points{ points = pts_of(P1.x, P1.y), style = "dot", size = 8, colour = "computed" }
fig:write(out .. "/diagram_convection.png")

print(string.format("one step, %d points: lamina's positions against the isoparametric update: %.2e",
                    P1.n, worst))
lamina.report{
  isoparametric_update = { worst, ref = 0, tol = 1e-12,
    unit = "largest |x_p' - sum_i N_i(x_p) (x_i + dt v_i)| ([T] eqs 3.20-3.21; round-off)" },
  state_hash = sim:hash(),
}
