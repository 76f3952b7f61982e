-- title: The local co-ordinate system of a membrane point: normal and tangent from its neighbours
-- source: York, Sulsky & Schreyer 1999 (membranes), §3, Fig 3; York, Sulsky & Schreyer 2000 (fluid-membrane), §3.2, Fig 4; York's dissertation, Fig 65
-- look: a curved membrane, its material points (solid circles) joined by the
--   dashed line of the contour; at point p the tangent t_p along the line
--   joining its two neighbours p-1 and p+1, and the normal n_p perpendicular to
--   it; the same frame drawn (smaller) at every point. Beside it, the close-up
--   of p and its neighbours
-- checks: on a stretched membrane lamina runs (connectivity normals, one
--   step): every interior point's normal perpendicular to x_{p+1} - x_{p-1}
--   ([M] §3: "perpendicular to a line connecting the two neighbouring material
--   points") and a unit vector; its stress the tangential one alone, sigma =
--   sigma_t t t ([M] §3: "a stress component tangent to the surface of the
--   membrane, with all other components zero"): |sigma n| / sigma_t, and
--   sigma_t = E eps_t for the uniaxial law
-- assumed: an arc of radius 0.6 over 100 degrees with 15 points, held, given
--   a tangential strain of 0.01; E 1e6, point forces (the papers')
-- thumb: diagram_local_frame.png
local sk = require("sketch")
local out = lamina.param("out", "out/diagram_local_frame")

local E, eps = 1e6, 0.01
local sim = lamina.sim{ basis = "linear", domain = {0, 0, 1.6, 1.0}, cell = 0.1, dt = 1e-7 }
local mem = sim:membrane{ material = lamina.membrane{ rho = 0.5, E = E, nu = 0, thickness = 0.1 },
                          curve = lamina.arc{ center = {0.8, 0.0}, radius = 0.6, from = 140, to = 40 },
                          count = 15, initial_strain = eps, force = "point", name = "membrane" }
mem:pin{ points = "all" }
sim:run{ t_end = 1e-7 }
local P = mem:particles()
local worst_perp, worst_unit, worst_sn, worst_st = 0, 0, 0, 0
for i = 2, P.n - 1 do
  local tx, ty = P.x[i + 1] - P.x[i - 1], P.y[i + 1] - P.y[i - 1]
  local l = math.sqrt(tx * tx + ty * ty)
  tx, ty = tx / l, ty / l
  local nx, ny = P.nx[i], P.ny[i]
  worst_perp = math.max(worst_perp, math.abs(nx * tx + ny * ty))
  worst_unit = math.max(worst_unit, math.abs(math.sqrt(nx * nx + ny * ny) - 1))
  local st = P.sxx[i] * tx * tx + 2 * P.sxy[i] * tx * ty + P.syy[i] * ty * ty
  local snx, sny = P.sxx[i] * nx + P.sxy[i] * ny, P.sxy[i] * nx + P.syy[i] * ny
  worst_sn = math.max(worst_sn, math.sqrt(snx * snx + sny * sny) / st)
  worst_st = math.max(worst_st, math.abs(st - E * P.et[i]) / (E * eps))
end

local fig = lamina.figure{ width = 1100, height = 520, panels = {2, 1},
  title = "[M] Fig 3 / [F] Fig 4 / [T] Fig 65: local co-ordinate system of a membrane point" }
local line = {}
for i = 1, P.n do line[i] = {P.x[i], P.y[i]} end
local k = 8   -- point p
local function frame_at(i, len, width)
  local tx, ty = P.x[i + 1] - P.x[i - 1], P.y[i + 1] - P.y[i - 1]
  local l = math.sqrt(tx * tx + ty * ty)
  fig:arrows{ at = {line[i], line[i]}, dir = {{tx / l, ty / l}, {P.nx[i], P.ny[i]}}, length = len,
              colour = "computed", width = width }
end
fig:panel{ index = 1, window = {0.1, 0.3, 1.5, 0.72}, title = "the membrane and every point's frame",
           caption = string.format("n_p . t_p to %.0e, |n_p| = 1 to %.0e over the interior points",
                                   worst_perp, worst_unit) }
fig:polyline{ points = line, colour = "black", dashed = true }
for i = 2, P.n - 1 do frame_at(i, 0.06, 1.2) end
fig:points{ points = line, style = "dot", size = 7, colour = "black" }
fig:panel{ index = 2, window = {P.x[k] - 0.2, P.y[k] - 0.15, P.x[k] + 0.2, P.y[k] + 0.17},
           title = "point p and its neighbours",
           caption = string.format("|sigma n| / sigma_t to %.0e; sigma_t = E eps_t to %.0e", worst_sn, worst_st) }
fig:polyline{ points = {line[k - 2], line[k - 1], line[k], line[k + 1], line[k + 2]}, colour = "black", dashed = true }
fig:polyline{ points = {line[k - 1], line[k + 1]}, colour = "grey", width = 1 }
frame_at(k, 0.1, 2)
local near = {}   -- only the points inside this panel's window (marks are not clipped)
for i = k - 2, k + 2 do near[#near + 1] = line[i] end
fig:points{ points = near, style = "dot", size = 10, colour = "black" }
fig:text{ text = "p", at = {P.x[k] - 0.012, P.y[k] - 0.03}, align = "center" }
fig:text{ text = "p-1", at = {P.x[k - 1], P.y[k - 1] - 0.03}, align = "center" }
fig:text{ text = "p+1", at = {P.x[k + 1], P.y[k + 1] - 0.03}, align = "center" }
fig:text{ text = "t_p", at = {P.x[k] + 0.1, P.y[k] + 0.015} }
fig:text{ text = "n_p", at = {P.x[k] + 0.01, P.y[k] + 0.11} }
sk.arrow(fig, {P.x[k] - 0.18, P.y[k] - 0.12}, {P.x[k] - 0.13, P.y[k] - 0.12}, "x")
sk.arrow(fig, {P.x[k] - 0.18, P.y[k] - 0.12}, {P.x[k] - 0.18, P.y[k] - 0.07}, "y")
fig:write(out .. "/diagram_local_frame.png")

print(string.format("n.t %.2e, |n|-1 %.2e, |sigma n|/sigma_t %.2e, sigma_t vs E eps_t %.2e",
                    worst_perp, worst_unit, worst_sn, worst_st))
lamina.report{
  normal_perpendicular = { worst_perp, ref = 0, tol = 1e-12, unit = "largest |n_p . t_p| ([M] §3)" },
  normal_unit = { worst_unit, ref = 0, tol = 1e-12, unit = "largest ||n_p| - 1|" },
  stress_tangential = { worst_sn, ref = 0, tol = 1e-12, unit = "largest |sigma n| / sigma_t ([M] §3)" },
  stress_law = { worst_st, ref = 0, tol = 1e-9, unit = "largest |sigma_t - E eps_t| / (E eps)" },
}
