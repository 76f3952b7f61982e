-- title: One material point in a cell: its mass matrix, lumped, and the grid mass it gives
-- source: York's dissertation [T] §3.4, Fig 10 (eqs 3.25-3.29)
-- look: a cell with its nodes 1-4 counter-clockwise from the lower left, one
--   material point p at logical (r, s) = (0.3, 0.6) with the shape function
--   value N_i beside each node; beside it the 4 x 4 mass matrix M_ij =
--   M_p N_i N_j (eq 3.26), its row sums M_p N_i, the lumped (diagonal) form
--   (eq 3.27), and the sum of all its entries, M_p (eqs 3.28-3.29: the grid
--   mass equals the material point mass)
-- checks: the sum of the matrix's entries and of its lumped diagonal
--   against M_p (eqs 3.28-3.29; round-off), with N_i from [T] App. A.3.1;
--   and the same conservation in lamina's own transfer: one point moving
--   at v in an otherwise empty grid, the kinetic energy of its momentum
--   mapped to the nodes (sim:energy().grid_kinetic, sum 1/2 |p_i|^2 / m_i,
--   m_i the lumped masses) against the point's 1/2 M_p v^2: equal exactly
--   when the lumped masses sum to M_p and the nodes share its velocity
--   (round-off; lamina seeds its one point at the cell centre, ppc = 1)
-- assumed: M_p = 1, a unit cell, the point at (0.3, 0.6) (Fig 10 gives no
--   place); lamina's linear basis (the papers')
-- thumb: diagram_mass_matrix.png
local out = lamina.param("out", "out/diagram_mass_matrix")

local Mp, r, s = 1.0, 0.3, 0.6
-- [T] App. A.3.1: nodes counter-clockwise from the lower left
local N = { (1 - r) * (1 - s), r * (1 - s), r * s, (1 - r) * s }
local node = { {0, 0}, {1, 0}, {1, 1}, {0, 1} }
local Mij, rows, total, diag = {}, {}, 0, 0
for i = 1, 4 do
  Mij[i], rows[i] = {}, 0
  for j = 1, 4 do
    Mij[i][j] = Mp * N[i] * N[j]          -- eq 3.26
    rows[i] = rows[i] + Mij[i][j]
    total = total + Mij[i][j]
  end
  diag = diag + rows[i]                   -- eq 3.27: the lumped form
end
local worst_row = 0
for i = 1, 4 do worst_row = math.max(worst_row, math.abs(rows[i] - Mp * N[i])) end

-- lamina's transfer: one point of mass Mp in a cell of a larger grid
local sim = lamina.sim{ basis = "linear", domain = {0, 0, 3, 3}, cell = 1, dt = 1e-3 }
local pt = sim:body{ material = lamina.elastic{ rho = Mp, E = 1, nu = 0 }, ppc = 1, name = "point",
                     region = lamina.rect{ x0 = 1, y0 = 1, x1 = 2, y1 = 2 }, velocity = {0.8, -0.5} }
local P = pt:particles()
local e = sim:energy()
local grid_miss = math.abs(e.grid_kinetic - e.kinetic) / e.kinetic

local fig = lamina.figure{ width = 1100, height = 560, panels = {2, 1},
  title = "[T] Fig 10: a single material point in a cell, and its mass matrix" }
fig:panel{ index = 1, window = {-0.35, -0.3, 1.35, 1.3}, title = "(a) one material point in a cell",
           caption = string.format("(r, s) = (%.1f, %.1f), [T] App. A.3.1's N_i", r, s) }
fig:polyline{ points = {node[1], node[2], node[3], node[4], node[1]}, colour = "black", width = 2 }
fig:points{ points = node, style = "circle", size = 10, colour = "black" }
fig:points{ points = {{r, s}}, style = "dot", size = 11, colour = "computed" }
fig:text{ text = "p", at = {r + 0.04, s + 0.04} }
local off = { {-0.2, -0.13}, {0.05, -0.13}, {0.05, 0.07}, {-0.2, 0.07} }
for i = 1, 4 do
  fig:text{ text = string.format("%d: N = %.2f", i, N[i]), at = {node[i][1] + off[i][1], node[i][2] + off[i][2]} }
end
fig:polyline{ points = {{0, s}, {r, s}}, colour = "grey", dashed = true }
fig:polyline{ points = {{r, 0}, {r, s}}, colour = "grey", dashed = true }
fig:text{ text = "r", at = {r / 2, -0.08}, align = "center" }
fig:text{ text = "s", at = {-0.07, s / 2}, align = "center" }
fig:panel{ index = 2, window = {0, 0, 1, 1}, title = "(b) M_ij = M_p N_i N_j (eq 3.26), lumped (3.27)",
           caption = string.format("entries sum to %.15g = M_p (3.28-3.29); lamina's grid mass: to %.0e",
                                   total, grid_miss) }
local cols = { 0.2, 0.36, 0.52, 0.68, 0.88 }
local y = 0.9
for j = 1, 4 do fig:text{ text = string.format("j = %d", j), at = {cols[j], y}, align = "center" } end
fig:text{ text = "M_p N_i", at = {cols[5], y}, align = "center" }
for i = 1, 4 do
  y = y - 0.11
  fig:text{ text = string.format("i = %d", i), at = {0.02, y} }
  for j = 1, 4 do fig:text{ text = string.format("%.4f", Mij[i][j]), at = {cols[j], y}, align = "center" } end
  fig:text{ text = string.format("%.4f", rows[i]), at = {cols[5], y}, align = "center" }
end
y = y - 0.16
fig:text{ text = string.format("lumped: diag(%.2f, %.2f, %.2f, %.2f), sum %.4g = M_p", rows[1], rows[2],
                               rows[3], rows[4], diag), at = {0.02, y} }
fig:write(out .. "/diagram_mass_matrix.png")

print(string.format("sum of M_ij %.17g, lumped %.17g (M_p %g); row sums against M_p N_i %.1e; "
  .. "lamina grid kinetic / kinetic - 1 = %.2e (%d point)", total, diag, Mp, worst_row, grid_miss, P.n))
lamina.report{
  matrix_sum = { total, ref = Mp, tol = 1e-12, unit = "sum of M_ij ([T] eqs 3.28-3.29: M_p; round-off)" },
  lumped_sum = { diag, ref = Mp, tol = 1e-12, unit = "sum of the lumped diagonal ([T] eq 3.27; round-off)" },
  row_sums = { worst_row, ref = 0, tol = 1e-12, unit = "largest |sum_j M_ij - M_p N_i| (round-off)" },
  lamina_grid_mass = { grid_miss, ref = 0, tol = 1e-12,
                       unit = "|grid_kinetic / kinetic - 1| for one moving point (lamina's lumped masses sum to M_p; round-off)" },
  state_hash = sim:hash(),
}
