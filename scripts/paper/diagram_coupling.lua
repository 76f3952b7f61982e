-- title: Fluid-structure coupling: fluid and membrane points load the same grid nodes, and move with one velocity field
-- source: York, Sulsky & Schreyer 2000 (fluid-membrane), §3, eq 17, Fig 2; York's dissertation, Fig 43
-- look: a grid node and the cells round it: fluid points (dots) and
--   membrane points (circles) in them both send their stress divergence to
--   the node (arrows): f_i = sum_f (div sigma_f) V_f + sum_m (div sigma_m) V_m
--   ([F] eq 17). The node's velocity then moves every point near it, so the
--   fluid and the membrane share one velocity field: no slip, no penetration
--   ([F] §3: "material points at the same location move together")
-- checks: a run of gas against a membrane in which one gas point and one
--   membrane point start at the same place: with the papers' point forces,
--   after 200 steps they are still at the same place with the same velocity,
--   to round-off (the closed form: both are moved by the same sum_i N_i v_i).
--   With lamina's segment forces (its default) the membrane's points move
--   with step 5's re-mapped velocity under MUSL (docs/api.md): the pair drifts
--   apart, 1.8e-3 cells here (printed)
-- assumed: gas at p = 1000 inside, a slack membrane (strain -0.02) across a
--   0.3-wide box, cell 0.1; the coincident pair at (0.15, 0.35)
-- thumb: diagram_coupling.png
local out = lamina.param("out", "out/diagram_coupling")

local h = 0.1
local function run(force)
  local sim = lamina.sim{ basis = "linear", domain = {0, 0, 0.3, 1}, cell = h, dt = 2e-5,
    boundary = { left = "symmetry", right = "symmetry", bottom = "fixed", top = "fixed" } }
  -- gas below y = 0.4 at one point a cell: the point of the cell (0.1-0.2, 0.3-0.4) at (0.15, 0.35)
  local gas = sim:body{ material = lamina.gas{ rho = 1, p = 1000 }, ppc = 1, name = "gas",
                        region = lamina.rect{ x0 = 0, y0 = 0, x1 = 0.3, y1 = 0.4 } }
  local mem = sim:membrane{ material = lamina.membrane{ rho = 0.5, E = 1e5, nu = 0, thickness = 0.01 },
                            curve = lamina.segment{ from = {0, 0.35}, to = {0.3, 0.35} }, count = 7,
                            initial_strain = -0.02, force = force, name = "membrane" }
  local G, M = gas:particles(), mem:particles()
  local function find(P, x, y)
    for k = 1, P.n do if math.abs(P.x[k] - x) < 1e-12 and math.abs(P.y[k] - y) < 1e-12 then return k end end
  end
  local kg, km = find(G, 0.15, 0.35), find(M, 0.15, 0.35)
  assert(kg and km, "no coincident gas and membrane points at (0.15, 0.35)")
  sim:run{ t_end = 200 * 2e-5 }
  G, M = gas:particles(), mem:particles()
  local r = { dpos = math.sqrt((G.x[kg] - M.x[km]) ^ 2 + (G.y[kg] - M.y[km]) ^ 2),
              dvel = math.sqrt((G.vx[kg] - M.vx[km]) ^ 2 + (G.vy[kg] - M.vy[km]) ^ 2),
              speed = math.sqrt(M.vx[km] ^ 2 + M.vy[km] ^ 2), moved = math.abs(M.y[km] - 0.35),
              hash = sim:hash() }
  return r
end
-- the papers' point forces: every point moves with the grid's v^L; lamina's
-- segment forces move a membrane's points with the re-mapped velocity of
-- step 5 under MUSL (docs/api.md, sim:membrane force), not the gas's
local pt, sg = run("point"), run("segment")
local dpos, dvel, speed, moved = pt.dpos, pt.dvel, pt.speed, pt.moved

local fig = lamina.figure{ width = 1100, height = 560, panels = {2, 1},
  title = "[F] Fig 2 / [T] Fig 43: fluid-structure coupling" }
fig:panel{ index = 1, window = {-0.05, -0.05, 2.05, 2.05}, title = "grid forces from both ([F] eq 17)" }
fig:grid{ box = {0, 0, 2, 2}, cells = {2, 2} }
local fluid = { {0.25, 0.3}, {0.75, 0.25}, {1.3, 0.3}, {1.75, 0.35}, {0.3, 0.75}, {1.25, 0.7}, {1.7, 0.65} }
local membrane = { {0.1, 1.0}, {0.5, 1.12}, {0.9, 1.18}, {1.3, 1.15}, {1.7, 1.05}, {1.95, 0.95} }
local node = {1, 1}
local at, dir = {}, {}
for _, set in ipairs{fluid, membrane} do
  for _, p in ipairs(set) do
    local dx, dy = node[1] - p[1], node[2] - p[2]
    local l = math.sqrt(dx * dx + dy * dy)
    if l < 0.9 then at[#at + 1], dir[#dir + 1] = p, {dx / l, dy / l} end
  end
end
fig:arrows{ at = at, dir = dir, length = 0.3, colour = "grey", width = 1 }
fig:polyline{ points = membrane, colour = "black", dashed = true }
fig:points{ points = fluid, style = "dot", size = 9, colour = "computed" }
fig:points{ points = membrane, style = "circle", size = 10, colour = "exact", width = 2 }
fig:points{ points = {node}, style = "dot", size = 12, colour = "black" }
fig:text{ text = "grid node i", at = {1.05, 0.92} }
fig:text{ text = "fluid points (f)", at = {0.1, 0.1}, colour = "computed" }
fig:text{ text = "membrane points (m)", at = {0.1, 1.85}, colour = "exact" }
fig:caption{ text = "f_i ~ sum_f (div sigma_f) V_f + sum_m (div sigma_m) V_m" }
fig:panel{ index = 2, window = {0, 0, 1, 1}, title = "one velocity field: a gas and a membrane point that start together",
           caption = string.format("after 200 steps: apart by %.1e, velocities differ by %.1e", dpos, dvel) }
local lines = {
  "gas below a slack membrane, p = 1000; one gas point and one",
  "membrane point start at (0.15, 0.35); the papers' point forces:",
  "",
  string.format("the membrane point moved %.4f, speed %.3f", moved, speed),
  string.format("distance between the pair: %.2e", dpos),
  string.format("difference of their velocities: %.2e", dvel),
  "",
  string.format("lamina's segment forces (its default): %.1e cells apart,", sg.dpos / h),
  "  their points move with step 5's re-mapped velocity (MUSL)",
  "[F] §3: \"material points at the same location move together\";",
  "\"there is no penetration of the fluid into the structure\"",
}
for i, l in ipairs(lines) do fig:text{ text = l, at = {0.03, 0.95 - 0.08 * i} } end
fig:write(out .. "/diagram_coupling.png")

print(string.format("pair after 200 steps: moved %.5f, speed %.4f, apart %.3e, velocity difference %.3e",
                    moved, speed, dpos, dvel))
lamina.report{
  pair_apart = { dpos / h, ref = 0, tol = 1e-12, unit = "cells between the two points" },
  pair_velocity = { dvel / speed, ref = 0, tol = 1e-12, unit = "of the speed" },
  pair_moved = { moved, unit = "(the pair's displacement)" },
  segment_pair_apart = { sg.dpos / h, unit = "cells (lamina's segment forces: step 5's velocity moves the membrane)" },
  state_hash = pt.hash,
}
