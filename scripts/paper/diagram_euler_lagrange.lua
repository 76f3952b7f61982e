-- title: Eulerian and Lagrangian descriptions of one deforming block: masses on a fixed grid, a mesh that moves with the material
-- source: York's dissertation [T] §1.1, Fig 1 (Eulerian (a) and Lagrangian (b) concepts)
-- look: [T]'s example: a block held by rollers on its right and bottom
--   sides and loaded by pressure on the other two (here a gas pushes it). (a)
--   Eulerian: the block as masses at the grid's nodes (circles, area
--   proportional to the mass) at t0 and at a later t1; the grid stays put,
--   the masses change ("convected"), and the material's edge (dashed) is
--   only a guess between nodes. (b) Lagrangian: the block as a mesh through
--   its material points that distorts with it; its edge is the mesh's edge
--   at every time. MPM uses both: this page's block is one lamina run, its
--   nodal masses (a) are those its grid carries each step, its mesh (b) the
--   lattice of its points
-- checks: (a) the nodal masses m_i = sum_p m_p N_ip sum to the block's mass
--   at t0 and t1 while single nodes change ([T] §1.1: the grid fixed, the
--   mass at its nodes changed), to round-off; (b) the mesh's nodes keep
--   their masses: the points' masses at t1 equal those at t0 exactly
-- assumed: [T] draws no sizes: a 2 x 2 block (rho 1, E 100, nu 0.3, plane
--   strain) in the corner of a 3 x 3 box of cells 0.25, 4 points a cell,
--   the papers' bilinear basis; the L-shaped rest of the box gas at p = 20
--   (rho 1, gamma 1.4; only its pressure is drawn, as arrows; lamina warns
--   that on the bilinear basis its sound speed is not the gas's, which does
--   not matter for a load); rollers on
--   every side; t1 = 0.4 (the block's left edge moved in 15 %)
-- thumb: diagram_euler_lagrange.png
local out = lamina.param("out", "out/diagram_euler_lagrange")

local h, L, t1 = 0.25, 3, 0.4
local sim = lamina.sim{ basis = "linear", domain = {0, 0, L, L}, cell = h, dt = 0.01,
                        boundary = "symmetry" }
local block = sim:body{ material = lamina.elastic{ rho = 1, E = 100, nu = 0.3, plane = "strain" },
                        ppc = 4, name = "block", region = lamina.rect{ x0 = 1, y0 = 0, x1 = 3, y1 = 2 } }
sim:body{ material = lamina.gas{ rho = 1, p = 20, gamma = 1.4 }, ppc = 4, name = "gas",
          region = function(x, y) return x < 1 or y > 2 end }

local P0 = block:particles()
local n = P0.n
-- the lattice of the block's points (b): each point's row and column at t0
local sp = h / 2
local col, row, at = {}, {}, {}
for p = 1, n do
  col[p] = math.floor((P0.x[p] - 1) / sp)
  row[p] = math.floor(P0.y[p] / sp)
  at[col[p] .. "," .. row[p]] = p
end
local ncol, nrow = math.floor(2 / sp), math.floor(2 / sp)

-- (a) the nodal masses of the bilinear basis, m_i = sum_p m_p N_ip
local function nodal(P)
  local m = {}
  for p = 1, P.n do
    local i, j = math.floor(P.x[p] / h), math.floor(P.y[p] / h)
    local r, s = P.x[p] / h - i, P.y[p] / h - j
    for _, w in ipairs{ {i, j, (1 - r) * (1 - s)}, {i + 1, j, r * (1 - s)},
                        {i + 1, j + 1, r * s}, {i, j + 1, (1 - r) * s} } do
      local k = w[1] + 100 * w[2]
      m[k] = (m[k] or 0) + P.mass[p] * w[3]
    end
  end
  return m
end
local function total(t)
  local s = 0
  for _, v in pairs(t) do s = s + v end
  return s
end

sim:run{ t_end = t1 }
local P1 = block:particles()
local m0, m1 = nodal(P0), nodal(P1)
local M = 0
for p = 1, n do M = M + P0.mass[p] end
local sum_err = math.max(math.abs(total(m0) - M), math.abs(total(m1) - M)) / M
local changed, mmax = 0, 0
for k, v in pairs(m0) do mmax = math.max(mmax, v) end
for k in pairs(m0) do changed = math.max(changed, math.abs((m1[k] or 0) - m0[k])) end
for k in pairs(m1) do if not m0[k] then changed = math.max(changed, m1[k]) end end
local mass_same = 0
for p = 1, n do mass_same = math.max(mass_same, math.abs(P1.mass[p] - P0.mass[p])) end
local squeeze = 1 - (function()
  local xmin = math.huge
  for p = 1, n do xmin = math.min(xmin, P1.x[p]) end
  return (3 - xmin) / (3 - (1 + sp / 2))
end)()

local sk = require("sketch")
local fig = lamina.figure{ width = 1000, height = 1000, panels = {2, 2},
  title = "[T] Fig 1: (a) Eulerian and (b) Lagrangian concepts" }
local win = {0.3, -0.35, 3.3, 2.65}
-- the set-up's marks: rollers on the right and bottom, the gas's pressure
-- on the left and top (arrows ending at the block's present edge)
local function setup(P)
  sk.wall(fig, {3, -0.05}, {3, 2.3}, { side = -1, hatch = 0.12 })
  sk.wall(fig, {0.6, 0}, {3.05, 0}, { side = -1, hatch = 0.12 })
  local xmin, ymax = math.huge, -math.huge
  for p = 1, P.n do xmin, ymax = math.min(xmin, P.x[p]), math.max(ymax, P.y[p]) end
  xmin, ymax = xmin - sp / 2, ymax + sp / 2
  for _, y in ipairs{ 0.5, 1.0, 1.5 } do
    sk.arrow(fig, {xmin - 0.4, y}, {xmin - 0.05, y}, y == 1.5 and "p" or nil, { dx = -0.3, dy = 0.1 })
  end
  for _, x in ipairs{ 1.5, 2.0, 2.5 } do
    sk.arrow(fig, {x, ymax + 0.4}, {x, ymax + 0.05}, x == 2.5 and "p" or nil, { dx = 0.05, dy = 0.25 })
  end
end
local function edge(P)
  -- the block's outline through its outer points, in lattice order
  local e = {}
  local function add(c, r) local p = at[c .. "," .. r]; e[#e + 1] = {P.x[p], P.y[p]} end
  for c = 0, ncol - 1 do add(c, 0) end
  for r = 1, nrow - 1 do add(ncol - 1, r) end
  for c = ncol - 2, 0, -1 do add(c, nrow - 1) end
  for r = nrow - 2, 0, -1 do add(0, r) end
  return e
end
local function eulerian(index, m, P, label)
  fig:panel{ index = index, window = win, title = label,
             caption = "circles: nodal masses (area); dashed: the edge, a guess" }
  fig:grid{ box = {0, 0, L, L}, cells = {L / h, L / h} }
  setup(P)
  local keys = {}
  for k in pairs(m) do keys[#keys + 1] = k end
  table.sort(keys)
  for _, k in ipairs(keys) do
    if m[k] > 1e-12 * mmax then
      fig:points{ points = { {(k % 100) * h, (k // 100) * h} }, style = "dot", colour = "computed",
                  size = 2 + 7 * math.sqrt(m[k] / mmax) }
    end
  end
  fig:polyline{ points = edge(P), colour = "black", width = 1.2, dashed = true }
end
local function lagrangian(index, P, label)
  fig:panel{ index = index, window = win, title = label,
             caption = "the mesh through the points distorts with the block" }
  setup(P)
  for r = 0, nrow - 1 do
    local line = {}
    for c = 0, ncol - 1 do local p = at[c .. "," .. r]; line[#line + 1] = {P.x[p], P.y[p]} end
    fig:polyline{ points = line, colour = "computed", width = 1 }
  end
  for c = 0, ncol - 1 do
    local line = {}
    for r = 0, nrow - 1 do local p = at[c .. "," .. r]; line[#line + 1] = {P.x[p], P.y[p]} end
    fig:polyline{ points = line, colour = "computed", width = 1 }
  end
end
eulerian(1, m0, P0, "(a) Eulerian, t0: masses at the fixed grid's nodes")
eulerian(2, m1, P1, string.format("(a) Eulerian, t1 = %.1f: the grid stays, the masses move", t1))
lagrangian(3, P0, "(b) Lagrangian, t0: a mesh on the material")
lagrangian(4, P1, string.format("(b) Lagrangian, t1 = %.1f: the mesh moves with it", t1))
fig:write(out .. "/diagram_euler_lagrange.png")

print(string.format("block %d points, mass %.4f; nodal sums off by %.1e; largest nodal change %.3f of the largest "
  .. "node's %.4f; left edge moved in %.1f %%", n, M, sum_err, changed / mmax, mmax, 100 * squeeze))
local rep = {
  nodal_mass_sum = { sum_err, ref = 0, tol = 1e-12,
    unit = "of the block's mass: sum_i m_i at t0 and t1 against sum_p m_p (round-off)" },
  nodal_mass_change = { changed / mmax, unit = "largest change of one node's mass, t0 to t1, of the largest (convected)" },
  point_mass_change = { mass_same, ref = 0, tol = 0, unit = "largest change of a point's mass (the mesh's nodes keep theirs)" },
  squeeze = { 100 * squeeze, unit = "% (the block's left edge moved in)" },
  state_hash = sim:hash(),
}
lamina.report(rep)
