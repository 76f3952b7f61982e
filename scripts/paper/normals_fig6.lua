-- title: Why the linear basis fails: two points with one logical coordinate get normals with one x-component (normals paper Fig 6)
-- source: normals paper Fig 6 ([N] §4, "Limitations of Linear Shape Functions", eq 15 and the text after it);
--   York's dissertation [T] §7.6, Figs 81 and 82 (eqs 7.15-7.17: the same analysis)
-- look: three points on a curve in one element, x_p1 and x_p2 at the same
--   height eta (the dotted line); their exact normals (dashed) have x-components
--   of opposite sign, but with the linear basis grad phi = (a + b eta, c + b xi)
--   ([N] §4), so the computed normals (solid) at x_p1 and x_p2 share the
--   x-component a + b eta whatever the nodal values. Here it is zero: along
--   the row eta the bilinear phi is linear in xi and equals 1 at both
--   points, so both computed normals point straight down.
--   Right ([T] Fig 81, nomenclature): the unit cell, its corner colours (the
--   fitted phi's nodal values) and x_p3's local coordinates (r, s); [T] eq
--   7.15 / [N] §4 writes the normal there as (a + b s, c + b r).
-- checks: the x-components of grad phi at x_p1 and x_p2 from lamina.normals'
--   fitted phi, equal to round-off ([N] §4's closed form), and the computed
--   normals' x-components, zero (phi linear along the row, 1 at both points);
--   the exact normals' x-components, which differ ([N]: "clearly ... do not
--   have the same x-component"); every computed normal against (a + b s, c + b r)
--   normalised, a, b, c from the corner colours (a = chi_2 - chi_1, b = chi_4 -
--   chi_3 - chi_2 + chi_1, c = chi_3 - chi_1, corners numbered as below)
-- assumed: the paper's figure has no coordinates: the points lie on the circle
--   (x - 0.5)^2 + (y - 0.5)^2 = 0.3^2 of [N] Fig 7, at 200, 240 and 340 degrees (x_p1, x_p3, x_p2);
--   the random point from seed 1
-- thumb: normals_fig6.png
local nu = require("normals_util")
local out = lamina.param("out", "out/normals_fig6")

local pts, ex = {}, {}
for _, deg in ipairs{200, 240, 340} do
  local t = math.rad(deg)
  pts[#pts + 1] = {0.5 + 0.3 * math.cos(t), 0.5 + 0.3 * math.sin(t)}
  ex[#ex + 1] = {math.cos(t), math.sin(t)}
end
-- the order as the paper numbers them: x_p1 and x_p2 share eta, x_p3 between
pts = {pts[1], pts[3], pts[2]}
ex = {ex[1], ex[3], ex[2]}
local r = lamina.normals{ points = pts, box = {0, 0, 1, 1}, basis = "linear", seed = 1,
                          orient = {0.5, 0.5} }
-- the bilinear phi's x-derivative at height eta is phi(1, eta) - phi(0, eta) exactly
local function gx(eta) return r.phi_at(1, eta) - r.phi_at(0, eta) end
local function gy(xi) return r.phi_at(xi, 1) - r.phi_at(xi, 0) end
local g1, g2 = gx(pts[1][2]), gx(pts[2][2])
local scale = math.max(math.abs(g1), math.abs(gy(pts[1][1])))
local worst = math.deg(nu.max_angle(r.normals, ex))

-- [T] eq 7.15 / [N] §4: grad phi = (a + b s, c + b r) in the cell's local
-- coordinates, a, b, c from the corner values (bilinear phi)
local c1, c2, c3, c4 = r.phi_at(0, 0), r.phi_at(1, 0), r.phi_at(0, 1), r.phi_at(1, 1)
local A, B, C = c2 - c1, c4 - c3 - c2 + c1, c3 - c1
local worst_form = 0
for i = 1, 3 do
  local rr, ss = pts[i][1], pts[i][2]
  local gxx, gyy = A + B * ss, C + B * rr
  local l = math.sqrt(gxx * gxx + gyy * gyy)
  local n = r.normals[i]
  worst_form = math.max(worst_form, math.abs(math.abs(n[1] * gxx + n[2] * gyy) / l - 1),
                        math.abs(n[1] * gyy - n[2] * gxx) / l)
end
local fig = lamina.figure{ width = 1300, height = 700, panels = {2, 1},
  title = "[N] Fig 6 / [T] Figs 81-82: x_p1 and x_p2 share the logical coordinate eta" }
fig:panel{ index = 1, window = {-0.08, -0.08, 1.08, 1.08}, title = "[N] Fig 6 / [T] Fig 82: three points in a unit cell",
           caption = string.format("phi = 1 on the row of x_p1, x_p2; n_x there %.0f, %.0f; exact %.2f, %.2f",
                                   math.abs(r.normals[1][1]), math.abs(r.normals[2][1]), ex[1][1], ex[2][1]) }
fig:polyline{ points = nu.circle(0.5, 0.5, 0.3, 72), dashed = true }
fig:normals{ result = r, points = pts, exact = ex, length = 0.18 }
fig:polyline{ points = {{0, pts[1][2]}, {1, pts[1][2]}}, colour = "grey", dashed = true }
for i, name in ipairs{"x_p1", "x_p2", "x_p3"} do
  fig:text{ text = name, at = {pts[i][1] + (i == 2 and 0.03 or -0.03), pts[i][2] + 0.04},
            align = i == 2 and "left" or "right" }
end
-- [T] Fig 81: the nomenclature of eq 7.15
fig:panel{ index = 2, window = {-0.25, -0.15, 1.25, 1.15}, title = "[T] Fig 81: local coordinates and grid colours",
           caption = string.format("a, b, c = %.2f, %.2f, %.2f; n = (a + b s, c + b r) to %.0e",
                                   A, B, C, worst_form) }
fig:outline{ box = {0, 0, 1, 1} }
fig:points{ points = {pts[3]}, style = "dot", size = 9, colour = "black" }
fig:polyline{ points = {{pts[3][1], 0}, {pts[3][1], pts[3][2]}, {0, pts[3][2]}}, colour = "grey", dashed = true }
fig:text{ text = "p (x_p3)", at = {pts[3][1] + 0.03, pts[3][2] + 0.03} }
fig:text{ text = string.format("r = %.3f", pts[3][1]), at = {pts[3][1], -0.07}, align = "center" }
fig:text{ text = string.format("s = %.3f", pts[3][2]), at = {-0.03, pts[3][2]}, align = "right" }
for _, cn in ipairs{ {0, 0, 1, c1}, {1, 0, 2, c2}, {0, 1, 3, c3}, {1, 1, 4, c4} } do
  fig:text{ text = string.format("chi_%d = %.3f", cn[3], cn[4]),
            at = {cn[1], cn[2] + (cn[2] == 0 and -0.07 or 0.04)}, align = "center" }
end
fig:write(out .. "/normals_fig6.png")

print(string.format("d phi/dx: x_p1 %.15g, x_p2 %.15g (difference %.3g); exact n_x %.4f / %.4f; "
  .. "computed n %.4f,%.4f / %.4f,%.4f; max error %.2f deg", g1, g2, g1 - g2, ex[1][1], ex[2][1],
  r.normals[1][1], r.normals[1][2], r.normals[2][1], r.normals[2][2], worst))
lamina.report{
  grad_x_difference = { math.abs(g1 - g2) / scale, ref = 0, tol = 1e-12,
                        unit = "of |grad phi| ([N] §4: (n_p)_x = a + b eta, the same at equal eta)" },
  normal_form = { worst_form, ref = 0, tol = 1e-12,
                  unit = "largest miss of n against (a + b s, c + b r) ([T] eq 7.15, [N] §4)" },
  computed_nx = { math.max(math.abs(r.normals[1][1]), math.abs(r.normals[2][1])), ref = 0, tol = 1e-12,
                  unit = "largest |n_x| at x_p1, x_p2 (phi linear along the row eta, 1 at both)" },
  exact_nx_difference = { ex[2][1] - ex[1][1], unit = "(the exact normals' x-components differ)" },
  max_error = { worst, unit = "deg (computed against exact; [N] Fig 6 gives none)" },
}
