-- title: Why the linear basis fails: two points with one logical coordinate get normals with one x-component (normals paper Fig 6)
-- source: normals paper Fig 6 ([N] §4, "Limitations of Linear Shape Functions", eq 15 and the text after it)
-- look: three points on a curve in one element, x_p1 and x_p2 at the same
--   height eta (the dotted line); their exact normals (dashed) have x-components
--   of opposite sign, but with the linear basis grad phi = (a + b eta, c + b xi)
--   ([N] §4), so the computed normals (solid) at x_p1 and x_p2 share the
--   x-component a + b eta whatever the nodal values. Here it is zero: along
--   the row eta the bilinear phi is linear in xi and equals 1 at both
--   points, so both computed normals point straight down.
-- checks: the x-components of grad phi at x_p1 and x_p2 from lamina.normals'
--   fitted phi, equal to round-off ([N] §4's closed form), and the computed
--   normals' x-components, zero (phi linear along the row, 1 at both points);
--   the exact normals' x-components, which differ ([N]: "clearly ... do not
--   have the same x-component")
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

local fig = lamina.figure{ width = 780, height = 700, panels = {1, 1},
  title = "Normals paper Fig 6: x_p1 and x_p2 share the logical coordinate eta" }
fig:panel{ index = 1, window = {-0.08, -0.08, 1.08, 1.08},
           caption = string.format("on the row eta of x_p1, x_p2 phi = 1; computed n_x there %.0f, %.0f; exact %.2f, %.2f",
                                   math.abs(r.normals[1][1]), math.abs(r.normals[2][1]), ex[1][1], ex[2][1]) }
fig:polyline{ points = nu.circle(0.5, 0.5, 0.3, 72), dashed = true }
fig:normals{ result = r, points = pts, exact = ex, length = 0.18 }
fig:polyline{ points = {{0, pts[1][2]}, {1, pts[1][2]}}, colour = "grey", dashed = true }
for i, name in ipairs{"x_p1", "x_p2", "x_p3"} do
  fig:text{ text = name, at = {pts[i][1] + (i == 2 and 0.03 or -0.03), pts[i][2] + 0.04},
            align = i == 2 and "left" or "right" }
end
fig:write(out .. "/normals_fig6.png")

print(string.format("d phi/dx: x_p1 %.15g, x_p2 %.15g (difference %.3g); exact n_x %.4f / %.4f; "
  .. "computed n %.4f,%.4f / %.4f,%.4f; max error %.2f deg", g1, g2, g1 - g2, ex[1][1], ex[2][1],
  r.normals[1][1], r.normals[1][2], r.normals[2][1], r.normals[2][2], worst))
lamina.report{
  grad_x_difference = { math.abs(g1 - g2) / scale, ref = 0, tol = 1e-12,
                        unit = "of |grad phi| ([N] §4: (n_p)_x = a + b eta, the same at equal eta)" },
  computed_nx = { math.max(math.abs(r.normals[1][1]), math.abs(r.normals[2][1])), ref = 0, tol = 1e-12,
                  unit = "largest |n_x| at x_p1, x_p2 (phi linear along the row eta, 1 at both)" },
  exact_nx_difference = { ex[2][1] - ex[1][1], unit = "(the exact normals' x-components differ)" },
  max_error = { worst, unit = "deg (computed against exact; [N] Fig 6 gives none)" },
}
