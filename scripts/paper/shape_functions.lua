-- title: The interpolation functions: linear on a cell's four nodes, quadratic on nine cell centres
-- source: York's dissertation [T] App. A.3, Figs 105 and 106, Tables 12 and 13
-- look: (a) Fig 105: a cell, its grid nodes numbered 1-4 counterclockwise
--   from the lower left, a material point p at logical (r, s) from node 1;
--   (b) Fig 106: for the quadratic functions r and s run from -0.5 to 0.5
--   about the cell's centre, and a point in cell 1 reaches the centres of
--   the nine cells numbered as Table 12 (1 its own, 2-5 right, top, left,
--   bottom, 6-9 the corners counterclockwise from the upper right)
-- checks: [T]'s formulas as printed, against lamina's own bases (the fits
--   of lamina.normals, whose phi is sum_I phi_I N_I): phi at 400 points of
--   the cell from Table 12's nine functions (quadratic) and from A.3.1's four
--   (linear), and the normal from Table 13's derivatives, all to round-off.
--   A.3.1 prints N4 = (1-s) r, which is N2's; its derivatives G4x = -s/dx,
--   G4y = (1-r)/dy are those of N4 = (1-r) s, used here (a misprint)
-- thumb: shape_functions.png
local out = lamina.param("out", "out/shape_functions")

-- [T] A.3.1 (N4 corrected) and Table 12 / Table 13, in its cell numbering;
-- off = the cell centre's offset (Fig 106(b))
local linear = {
  { node = {0, 0}, f = function(r, s) return (1 - r) * (1 - s) end },
  { node = {1, 0}, f = function(r, s) return r * (1 - s) end },
  { node = {1, 1}, f = function(r, s) return r * s end },
  { node = {0, 1}, f = function(r, s) return (1 - r) * s end },
}
local quad = {
  { off = {0, 0}, f = function(r, s) return (0.75 - r * r) * (0.75 - s * s) end,
    dx = function(r, s) return -2 * r * (0.75 - s * s) end, dy = function(r, s) return -2 * s * (0.75 - r * r) end },
  { off = {1, 0}, f = function(r, s) return 0.5 * (0.5 + r) ^ 2 * (0.75 - s * s) end,
    dx = function(r, s) return (0.5 + r) * (0.75 - s * s) end, dy = function(r, s) return -s * (0.5 + r) ^ 2 end },
  { off = {0, 1}, f = function(r, s) return 0.5 * (0.75 - r * r) * (0.5 + s) ^ 2 end,
    dx = function(r, s) return -r * (0.5 + s) ^ 2 end, dy = function(r, s) return (0.75 - r * r) * (0.5 + s) end },
  { off = {-1, 0}, f = function(r, s) return 0.5 * (0.5 - r) ^ 2 * (0.75 - s * s) end,
    dx = function(r, s) return -(0.5 - r) * (0.75 - s * s) end, dy = function(r, s) return -s * (0.5 - r) ^ 2 end },
  { off = {0, -1}, f = function(r, s) return 0.5 * (0.75 - r * r) * (0.5 - s) ^ 2 end,
    dx = function(r, s) return -r * (0.5 - s) ^ 2 end, dy = function(r, s) return -(0.75 - r * r) * (0.5 - s) end },
  { off = {1, 1}, f = function(r, s) return 0.25 * ((0.5 + r) * (0.5 + s)) ^ 2 end,
    dx = function(r, s) return 0.5 * (0.5 + r) * (0.5 + s) ^ 2 end, dy = function(r, s) return 0.5 * (0.5 + s) * (0.5 + r) ^ 2 end },
  { off = {-1, 1}, f = function(r, s) return 0.25 * ((0.5 - r) * (0.5 + s)) ^ 2 end,
    dx = function(r, s) return -0.5 * (0.5 - r) * (0.5 + s) ^ 2 end, dy = function(r, s) return 0.5 * (0.5 + s) * (0.5 - r) ^ 2 end },
  { off = {-1, -1}, f = function(r, s) return 0.25 * ((0.5 - r) * (0.5 - s)) ^ 2 end,
    dx = function(r, s) return -0.5 * (0.5 - r) * (0.5 - s) ^ 2 end, dy = function(r, s) return -0.5 * (0.5 - s) * (0.5 - r) ^ 2 end },
  { off = {1, -1}, f = function(r, s) return 0.25 * ((0.5 + r) * (0.5 - s)) ^ 2 end,
    dx = function(r, s) return 0.5 * (0.5 + r) * (0.5 - s) ^ 2 end, dy = function(r, s) return -0.5 * (0.5 - s) * (0.5 + r) ^ 2 end },
}

-- fits with every nodal value determined (points on a cubic, not a conic)
local pts = {}
for k = 1, 10 do
  local x = 0.05 + 0.9 * (k - 1) / 9
  pts[k] = {x, 0.15 + 0.7 * x ^ 3}
end
local rl = lamina.normals{ points = {pts[2], pts[5], pts[9]}, box = {0, 0, 1, 1}, basis = "linear", seed = 3 }
local rq = lamina.normals{ points = pts, box = {0, 0, 1, 1}, basis = "quadratic", seed = 3 }
-- the nodal values by position: linear node I = i + 2 j, quadratic centre
-- I = i + 3 j at offset (i - 1, j - 1) (docs/api.md, lamina.normals: phi)
local function lin_phi(n) return rl.phi[1 + n[1] + 2 * n[2]] end
local function quad_phi(o) return rq.phi[1 + (o[1] + 1) + 3 * (o[2] + 1)] end
local worst_l, worst_q, worst_n, worst_pu = 0, 0, 0, 0
for a = 0, 19 do
  for b = 0, 19 do
    local x, y = (a + 0.5) / 20, (b + 0.5) / 20
    local vl = 0
    for _, N in ipairs(linear) do vl = vl + lin_phi(N.node) * N.f(x, y) end
    worst_l = math.max(worst_l, math.abs(vl - rl.phi_at(x, y)))
    local r, s = x - 0.5, y - 0.5
    local vq, sum = 0, 0
    for _, S in ipairs(quad) do
      vq = vq + quad_phi(S.off) * S.f(r, s)
      sum = sum + S.f(r, s)
    end
    worst_q = math.max(worst_q, math.abs(vq - rq.phi_at(x, y)))
    worst_pu = math.max(worst_pu, math.abs(sum - 1))
  end
end
-- Table 13: the gradient at the membrane points against lamina's normals
for i, p in ipairs(pts) do
  local r, s = p[1] - 0.5, p[2] - 0.5
  local gx, gy = 0, 0
  for _, S in ipairs(quad) do
    gx, gy = gx + quad_phi(S.off) * S.dx(r, s), gy + quad_phi(S.off) * S.dy(r, s)
  end
  local l = math.sqrt(gx * gx + gy * gy)
  local n = rq.normals[i]
  worst_n = math.max(worst_n, math.abs(n[1] * gy - n[2] * gx) / l)
end
local scale = 0
for _, v in ipairs(rq.phi) do scale = math.max(scale, math.abs(v)) end

local fig = lamina.figure{ width = 1100, height = 560, panels = {2, 1},
  title = "[T] Figs 105-106, Tables 12-13: the interpolation functions" }
fig:panel{ index = 1, window = {-0.3, -0.3, 1.3, 1.3}, title = "(a) Fig 105: nomenclature (linear)",
           caption = string.format("A.3.1's N1-N4 against lamina's bilinear phi: %.0e", worst_l) }
fig:outline{ box = {0, 0, 1, 1}, width = 2 }
for k, N in ipairs(linear) do
  fig:points{ points = {N.node}, style = "dot", size = 8, colour = "black" }
  fig:text{ text = tostring(k), at = {N.node[1] + (N.node[1] == 0 and -0.06 or 0.04), N.node[2] + (N.node[2] == 0 and -0.07 or 0.03)} }
end
local p = {0.62, 0.38}
fig:points{ points = {p}, style = "dot", size = 9, colour = "computed" }
fig:text{ text = "p", at = {p[1] + 0.03, p[2] + 0.03}, colour = "computed" }
fig:polyline{ points = {{p[1], 0}, p, {0, p[2]}}, colour = "grey", dashed = true }
fig:text{ text = "r", at = {p[1], -0.08}, align = "center" }
fig:text{ text = "s", at = {-0.06, p[2]}, align = "right" }
fig:text{ text = "dx", at = {0.5, 1.05}, align = "center" }
fig:text{ text = "dy", at = {1.05, 0.5} }
fig:text{ text = "grid nodes numbered counterclockwise", at = {0.5, 1.18}, align = "center" }
fig:panel{ index = 2, window = {-1.7, -1.7, 1.7, 1.7}, title = "(b) Fig 106: quadratic, nine cell centres",
           caption = string.format("Table 12 against lamina's quadratic phi: %.0e; Table 13's normals: %.0e",
                                   worst_q / scale, worst_n) }
fig:grid{ box = {-1.5, -1.5, 1.5, 1.5}, cells = {3, 3} }
fig:outline{ box = {-0.5, -0.5, 0.5, 0.5}, width = 2 }
for k, S in ipairs(quad) do
  fig:points{ points = {S.off}, style = "asterisk", size = 10, colour = "black" }
  fig:text{ text = tostring(k), at = {S.off[1] + 0.08, S.off[2] + 0.08} }
end
fig:arrows{ at = {{0, 0}, {0, 0}}, dir = {{1, 0}, {0, 1}}, length = 0.45, colour = "computed", width = 1.4 }
fig:text{ text = "r", at = {0.42, -0.14}, colour = "computed" }
fig:text{ text = "s", at = {-0.14, 0.4}, colour = "computed" }
fig:text{ text = "cell 1: -0.5 <= r, s <= 0.5 about its centre", at = {0, -1.64}, align = "center" }
fig:write(out .. "/shape_functions.png")

print(string.format("linear: %.2e; quadratic: %.2e (of max |phi| %.3g); normals %.2e; partition of unity %.2e",
                    worst_l, worst_q, scale, worst_n, worst_pu))
lamina.report{
  linear_functions = { worst_l, ref = 0, tol = 1e-12, unit = "largest |phi - sum phi_I N_I| ([T] A.3.1)" },
  quadratic_functions = { worst_q / scale, ref = 0, tol = 1e-12,
                          unit = "largest |phi - sum phi_c S_c| / max |phi_c| ([T] Table 12)" },
  quadratic_derivatives = { worst_n, ref = 0, tol = 1e-9, unit = "largest |n x grad| / |grad| ([T] Table 13)" },
  partition_of_unity = { worst_pu, ref = 0, tol = 1e-14, unit = "(Table 12's nine sum to 1)" },
}
