-- gas_nodes.lua - a gas's pressure at the grid's nodes, and its mean over
-- the nodes inside a membrane: [T] Table 5 note c, "Calculated by averaging
-- the final pressure at interior grid points" (issue 32 item 7).
--
-- The nodal pressure is the one the grid's momentum equation feels: a gas
-- point pushes the grid with V_p p_p = (gamma - 1) m_p e_p ([F] eq 15 with
-- eq 21), so the pressure at node i is the energy density there,
--     P_i = (gamma - 1) sum_p m_p e_p N_ip / V_i,   V_i = h^2,
-- exactly (gamma - 1) rho e wherever the node's whole support lies in a
-- uniform gas (partition of unity), and the fraction of it the gas covers
-- at a node near the gas's edge (src/mpm/diag_gas.c reads the same field).
-- The mass-weighted map, sum m_p p_p N_ip / sum m_p N_ip (the pressure
-- contours' field, [T] Fig 56), is given beside it: it reads the points'
-- own (gamma - 1) rho_p e_p, whose continuity densities drift from the
-- points' spacing (docs/api.md gas:pressure("particles")).
--
-- N_ip is the sim's basis (bilinear, or the node-centred quadratic B-spline
-- of src/mpm/shape_bspline.c). Symmetry walls at x = x0 and y = y0 (a
-- quarter model) are taken as mirrors: the gas is reflected across them,
-- so that a node on the axis sees its whole support as in the full problem
-- (the engine's fold leaves such a node half its own image: diag_gas.c).
--
--   local gn = require("gas_nodes")
--   local r = gn.inside(sim, gas, polygon_points, {domain = {0, 0, 1.6, 1.6},
--                       mirror = {x = 0, y = 0}})   -- basis: the sim's
--   r.energy (mean P_i), r.mass (mean mass-weighted), r.nodes (count)
--   gn.reached(sim, gas, {domain = ...}): the mean P_i over the grid's
--   interior nodes (off the domain's boundary) that the gas reaches
local M = {}

-- one axis' weights: {node, weight} pairs for coordinate u, cell h, origin u0
local function weights(u, u0, h, basis)
  local s = (u - u0) / h
  if basis == "linear" then
    local i = math.floor(s)
    return { { i, 1 - (s - i) }, { i + 1, s - i } }
  elseif basis == "bspline2" then
    local i = math.floor(s + 0.5)
    local w = {}
    for k = i - 1, i + 1 do
      local xi = math.abs(s - k)
      w[#w + 1] = { k, xi <= 0.5 and 0.75 - xi * xi or 0.5 * (1.5 - xi) ^ 2 }
    end
    return w
  end
  error("gas_nodes: basis '" .. tostring(basis) .. "' is not one of \"linear\", \"bspline2\"", 3)
end

-- the same weights for other scripts (scripts/measure/dogbone_pressure_defs.lua)
M.weights = weights

-- The nodal sums of the gas: energy[key] = sum m e N, mass[key] = sum m N,
-- mp[key] = sum m p N, keys j * (nx + 1) + i for nodes i, j of the grid.
function M.sums(sim, gas, o)
  o = o or {}
  local basis = o.basis or sim.basis
  local d = o.domain or error("gas_nodes: 'domain' ({x0, y0, x1, y1}, the sim's) is required", 2)
  local x0, y0, h = d[1], d[2], sim.cell
  local nx = math.floor((d[3] - x0) / h + 0.5)
  local ny = math.floor((d[4] - y0) / h + 0.5)
  local mx, my = o.mirror and o.mirror.x, o.mirror and o.mirror.y
  local g = gas:particles()
  local S = { energy = {}, mass = {}, mp = {}, nx = nx, ny = ny, h = h, x0 = x0, y0 = y0 }
  for q = 1, #gas do
    local me, m, mp = g.mass[q] * g.e[q], g.mass[q], g.mass[q] * g.p[q]
    for sx = 0, mx and 1 or 0 do
      for sy = 0, my and 1 or 0 do
        local px = sx == 1 and 2 * mx - g.x[q] or g.x[q]
        local py = sy == 1 and 2 * my - g.y[q] or g.y[q]
        for _, a in ipairs(weights(px, x0, h, basis)) do
          for _, c in ipairs(weights(py, y0, h, basis)) do
            if a[1] >= 0 and a[1] <= nx and c[1] >= 0 and c[1] <= ny then
              local key, N = c[1] * (nx + 1) + a[1], a[2] * c[2]
              S.energy[key] = (S.energy[key] or 0) + me * N
              S.mass[key] = (S.mass[key] or 0) + m * N
              S.mp[key] = (S.mp[key] or 0) + mp * N
            end
          end
        end
      end
    end
  end
  return S
end

-- The means over the grid's nodes that lie inside the polygon `points`
-- ({{x, y}, ...}; a membrane's points closed as the caller wants): energy
-- (P_i), mass (mass-weighted; a node inside with no gas counts 0), nodes.
function M.inside(sim, gas, points, o)
  o = o or {}
  local gamma1 = o.gamma1 or 0.4
  local S = M.sums(sim, gas, o)
  local poly = lamina.polygon{ points = points }
  local r = { energy = 0, mass = 0, nodes = 0 }
  for j = 0, S.ny do
    for i = 0, S.nx do
      if poly:contains(S.x0 + i * S.h, S.y0 + j * S.h) then
        local key = j * (S.nx + 1) + i
        r.energy = r.energy + gamma1 * (S.energy[key] or 0) / (S.h * S.h)
        r.mass = r.mass + ((S.mass[key] or 0) > 0 and S.mp[key] / S.mass[key] or 0)
        r.nodes = r.nodes + 1
      end
    end
  end
  if r.nodes > 0 then r.energy, r.mass = r.energy / r.nodes, r.mass / r.nodes end
  return r
end

-- The other reading of "interior grid points": the grid's nodes off the
-- domain's boundary that the gas reaches (sum m N > 0), whether inside the
-- membrane or not; a node the gas only partly covers reads the part.
function M.reached(sim, gas, o)
  o = o or {}
  local gamma1 = o.gamma1 or 0.4
  local S = M.sums(sim, gas, o)
  local r = { energy = 0, nodes = 0 }
  for j = 1, S.ny - 1 do
    for i = 1, S.nx - 1 do
      local key = j * (S.nx + 1) + i
      if (S.mass[key] or 0) > 0 then
        r.energy = r.energy + gamma1 * S.energy[key] / (S.h * S.h)
        r.nodes = r.nodes + 1
      end
    end
  end
  if r.nodes > 0 then r.energy = r.energy / r.nodes end
  return r
end

return M
