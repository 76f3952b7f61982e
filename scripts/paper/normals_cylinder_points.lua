-- title: The normals model problem: a quarter cylinder, and its material points with no fluid, 4 and 16 per cell
-- source: York's dissertation [T] §7.5, Fig 66 (a-b)
-- look: (a) the model problem in quarter symmetry: the cylinder of radius 1.0,
--   symmetry lines along the axes, the walls at x, y = 1.5 (§7.5.2); (b) its
--   material points: the membrane alone (vacuum inside), then with fluid
--   points inside at 4 and at 16 points per cell
-- checks: on the points lamina seeds: 4 and 16 fluid points in every cell
--   the fluid covers, none outside the cylinder; the membrane points on the
--   radius 1.0 circle
-- assumed: [T] gives no grid or point count: cells of 0.1 on [0, 1.5]^2 and 46
--   membrane points (as normals_variants_cylinder: half a cell apart), the
--   fluid seeded by the papers' rule (sub-cell centres inside the circle)
-- thumb: normals_cylinder_points.png
local out = lamina.param("out", "out/normals_cylinder_points")

local h, R = 0.1, 1.0
local function seed(ppc)
  local sim = lamina.sim{ basis = "linear", domain = {0, 0, 1.5, 1.5}, cell = h, dt = 1e-5,
    boundary = { left = "symmetry", bottom = "symmetry", right = "fixed", top = "fixed" } }
  local mem = sim:membrane{ material = lamina.membrane{ rho = 0.5, E = 1e6, nu = 0.3, thickness = 0.1 },
                            curve = lamina.arc{ center = {0, 0}, radius = R, from = 0, to = 90 },
                            count = 46, name = "membrane" }
  local gas
  if ppc > 0 then
    gas = sim:body{ material = lamina.gas{ rho = 1, p = 1000 }, ppc = ppc, name = "fluid",
                    region = lamina.disk{ center = {0, 0}, radius = R } }
  end
  return mem:particles(), gas and gas:particles()
end

local fig = lamina.figure{ width = 1200, height = 420, panels = {4, 1},
  title = "[T] Fig 66: (a) the quarter symmetry model problem, (b) its points: none, 4 and 16 per cell" }
fig:panel{ index = 1, window = {-0.1, -0.1, 1.6, 1.6}, title = "(a) model problem" }
local arc = {}
for k = 0, 90 do arc[#arc + 1] = {R * math.cos(math.rad(k)), R * math.sin(math.rad(k))} end
fig:polyline{ points = arc, colour = "black", width = 2.5 }
fig:polyline{ points = {{0, 0}, {1.5, 0}, {1.5, 1.5}, {0, 1.5}, {0, 0}}, colour = "grey" }
fig:text{ text = "symmetry", at = {0.75, 0.04}, align = "center" }
fig:text{ text = "R = 1.0", at = {0.45, 0.45} }
fig:text{ text = "wall at 1.5", at = {1.45, 1.55}, align = "right" }
local worst_r, counts, outside = 0, {}, 0
local whole = 0   -- the cells wholly inside the circle, counted on the grid
for i = 0, 14 do for j = 0, 14 do
  if ((i + 1) * h) ^ 2 + ((j + 1) * h) ^ 2 < R * R then whole = whole + 1 end
end end
for i, ppc in ipairs{0, 4, 16} do
  local M, G = seed(ppc)
  for k = 1, M.n do worst_r = math.max(worst_r, math.abs(math.sqrt(M.x[k] ^ 2 + M.y[k] ^ 2) - R)) end
  fig:panel{ index = i + 1, window = {-0.05, -0.05, 1.1, 1.1},
             title = ppc == 0 and "(b) no fluid" or string.format("(b) %d PPC fluid", ppc) }
  fig:grid{ box = {0, 0, 1.1, 1.1}, cells = {11, 11} }
  if G then
    local per, pts = {}, {}
    for k = 1, G.n do
      pts[k] = {G.x[k], G.y[k]}
      if G.x[k] ^ 2 + G.y[k] ^ 2 > R * R then outside = outside + 1 end
      local key = math.floor(G.x[k] / h) .. ":" .. math.floor(G.y[k] / h)
      per[key] = (per[key] or 0) + 1
    end
    local full, most = 0, 0
    for key, c in pairs(per) do
      local cx, cy = key:match("(%-?%d+):(%-?%d+)")
      cx, cy = tonumber(cx), tonumber(cy)
      -- a cell wholly inside the circle must hold ppc points
      if ((cx + 1) * h) ^ 2 + ((cy + 1) * h) ^ 2 < R * R then
        full = full + 1
        if c ~= ppc then most = math.max(most, math.abs(c - ppc)) end
      end
    end
    most = math.max(most, (whole - full) * ppc)   -- a whole cell with no point
    counts[ppc] = { full = full, off = most }
    fig:points{ points = pts, style = "dot", size = ppc == 4 and 3 or 2, colour = "computed" }
  end
  local mp = {}
  for k = 1, M.n do mp[k] = {M.x[k], M.y[k]} end
  fig:points{ points = mp, style = "circle", size = 5, colour = "exact" }
end
fig:write(out .. "/normals_cylinder_points.png")

print(string.format("membrane off radius %.2e; 4 ppc: %d whole cells, largest miss %d; 16 ppc: %d whole cells, "
  .. "largest miss %d; fluid points outside %d", worst_r, counts[4].full, counts[4].off, counts[16].full,
  counts[16].off, outside))
lamina.report{
  membrane_radius = { worst_r, ref = 0, tol = 1e-12, unit = "largest |r - 1.0| of the membrane points" },
  ppc_4 = { counts[4].off, ref = 0, tol = 0, unit = string.format("largest miss of 4 points in the %d whole cells", counts[4].full) },
  ppc_16 = { counts[16].off, ref = 0, tol = 0, unit = string.format("largest miss of 16 points in the %d whole cells", counts[16].full) },
  fluid_outside = { outside, ref = 0, tol = 0, unit = "fluid points outside the cylinder" },
}
