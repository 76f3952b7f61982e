-- assets/lua/gas_nodes.lua (the nodal gas pressure behind gas_dogbone's
-- [T] Table 5 note c reading) against exact values on a uniform gas at
-- rest (rho 1, e 250, gamma 1.4: p = 100 at every point), no step taken:
--   * a node whose support lies wholly in the gas reads (gamma - 1) rho e
--     = 100 (partition of unity), on both bases;
--   * bilinear, a gas square on cell lines: a node on its edge reads 50 (half
--     its support covered), on its corner 25; the mass-weighted map reads
--     100 wherever the gas reaches;
--   * the mean over the nodes inside a polygon is the mean of those values
--     (counted by hand below), and agrees with the engine's gas:pressure()
--     (its nodes wholly in the gas) where the polygon holds only such nodes;
--   * mirrored across symmetry walls at x = 0 and y = 0, a quarter gas's
--     nodes on the axes read the full 100 (the engine's own fold leaves them
--     half: src/mpm/diag_gas.c).
local gn = require("gas_nodes")
local function close(a, b, what) assert(math.abs(a - b) < 1e-9, string.format("%s: %.12g, expected %.12g", what, a, b)) end

for _, basis in ipairs{"linear", "bspline2"} do
  local sim = lamina.sim{ domain = {0, 0, 1, 1}, cell = 0.1, dt = 1e-4, basis = basis }
  local air = lamina.gas{ rho = 1, e = 250, gamma = 1.4 }
  local gas = sim:body{ material = air, ppc = 4, region = lamina.rect{x0 = 0.2, y0 = 0.2, x1 = 0.8, y1 = 0.8}, name = "gas" }
  local S = gn.sums(sim, gas, { domain = {0, 0, 1, 1} })
  local function P(i, j) return 0.4 * (S.energy[j * 11 + i] or 0) / 0.01 end
  close(P(5, 5), 100, basis .. ": the middle node")
  close(P(4, 6), 100, basis .. ": a node wholly in the gas")
  close(S.mp[5 * 11 + 2] / S.mass[5 * 11 + 2], 100, basis .. ": mass-weighted at the gas's edge")
  if basis == "linear" then
    close(P(2, 5), 50, "linear: a node on the gas's edge")
    close(P(2, 2), 25, "linear: the gas's corner node")
    close(P(1, 5), 0, "linear: a node a cell outside")
  else
    -- the quadratic B-spline's node on the edge: half the support covered
    -- along x (the spline is symmetric about its node)
    close(P(2, 5), 50, "bspline2: a node on the gas's edge")
  end
  -- nodes x, y in {0.3 ... 0.7}: wholly in the gas for the linear basis
  local r = gn.inside(sim, gas, { {0.25, 0.25}, {0.75, 0.25}, {0.75, 0.75}, {0.25, 0.75} }, { domain = {0, 0, 1, 1} })
  assert(r.nodes == 25, basis .. ": 25 nodes inside, got " .. r.nodes)
  close(r.mass, 100, basis .. ": mass-weighted mean inside")
  if basis == "linear" then
    close(r.energy, 100, "linear: the mean over nodes wholly in the gas")
    close(r.energy, gas:pressure(), "linear: the engine's gas:pressure() over its nodes wholly in the gas")
  else
    -- 0.3 and 0.7 lie a cell from the edge, inside the B-spline's 1.5
    -- cells: only the 9 middle nodes are wholly in the gas
    local inner = gn.inside(sim, gas, { {0.35, 0.35}, {0.65, 0.35}, {0.65, 0.65}, {0.35, 0.65} },
                            { domain = {0, 0, 1, 1} })
    assert(inner.nodes == 9, "bspline2: 9 inner nodes")
    close(inner.energy, 100, "bspline2: the mean over nodes wholly in the gas")
    -- a node one cell in from the edge misses the spline's tail on the
    -- points beyond the edge: with 2 points a cell along x at 1/4 and 3/4,
    -- the one at 1.25 cells out weighs (1/2)(3/2 - 5/4)^2 = 1/32, and each
    -- point stands for half a cell: 1 - 1/64 of the support covered
    close(P(3, 5), 100 * (1 - 1 / 64), "bspline2: a node a cell in from the edge")
    assert(r.energy < 100 and r.energy > 95, "bspline2: the 5 x 5 mean reads the edge rows' shortfall")
  end
end

-- the grid's interior nodes the gas reaches: on the linear basis the 7 x 7
-- nodes 0.2 ... 0.8, of which 5 x 5 read 100, the 20 on the edge 50 but the
-- 4 corners 25: (25 * 100 + 20 * 50 + 4 * 25) / 49
do
  local sim = lamina.sim{ domain = {0, 0, 1, 1}, cell = 0.1, dt = 1e-4, basis = "linear" }
  local gas = sim:body{ material = lamina.gas{ rho = 1, e = 250, gamma = 1.4 }, ppc = 4,
                        region = lamina.rect{x0 = 0.2, y0 = 0.2, x1 = 0.8, y1 = 0.8}, name = "gas" }
  local r = gn.reached(sim, gas, { domain = {0, 0, 1, 1} })
  assert(r.nodes == 49, "reached: 49 nodes, got " .. r.nodes)
  close(r.energy, (25 * 100 + 20 * 50 + 4 * 25) / 49, "reached: the mean over the nodes the gas reaches")
end

-- a quarter gas against symmetry walls at x = 0, y = 0, mirrored
do
  local sim = lamina.sim{ domain = {0, 0, 1, 1}, cell = 0.1, dt = 1e-4, basis = "linear",
                          boundary = { left = "symmetry", bottom = "symmetry" } }
  local air = lamina.gas{ rho = 1, e = 250, gamma = 1.4 }
  local gas = sim:body{ material = air, ppc = 4, region = lamina.rect{x0 = 0, y0 = 0, x1 = 0.5, y1 = 0.5}, name = "gas" }
  local S = gn.sums(sim, gas, { domain = {0, 0, 1, 1}, mirror = { x = 0, y = 0 } })
  local U = gn.sums(sim, gas, { domain = {0, 0, 1, 1} })
  close(0.4 * S.energy[0] / 0.01, 100, "mirrored: the corner node (0, 0)")
  close(0.4 * S.energy[3] / 0.01, 100, "mirrored: a node on the x axis")
  close(0.4 * U.energy[3] / 0.01, 50, "not mirrored: a node on the x axis reads half")
  close(0.4 * U.energy[0] / 0.01, 25, "not mirrored: the corner node reads a quarter")
end
print("gas_nodes: nodal pressures as the partition of unity gives them, on both bases")
