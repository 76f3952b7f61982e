-- title: The mass matrix method on a circular arc rotated in its cell: points at one height get one n_x (dissertation Figs 83-84)
-- source: York's dissertation [T] §7.6, Figs 83 and 84 (eq 7.17 and the text before them); §7.7, Fig 85
-- look: four panels, the same five-point arc turned about the cell's centre by
--   45, 30, 15 and 0 degrees: colour contours (grey, the bold one colour 1),
--   exact normals dashed, computed solid. As the arc turns upright, pairs of
--   points come to the same height and their computed normals to the same
--   x-component ([T] eq 7.17: at equal local y the two equations have one
--   left-hand side), while the exact ones are mirror images; in the last panel
--   (Fig 84, bottom) the pairs at identical y are labelled and the error is largest.
--   fig85.png ([T] Fig 85): the same points as Fig 84 (bottom) with the
--   quadratic functions on the nine cell centres ([T] §7.7): the computed
--   normals lie on the exact ones and the colour 1 contour is a near circle
--   through the points
-- checks: Fig 85: the quadratic normals' largest error against the exact, within 1
--   degree ([T]: "lay on top of the theoretical ones"; 1 degree is ours, a
--   quarter of an arrow head at the figure's scale), by lamina's QR solve
--   (minimum norm: 5 points and the extra point leave 9 unknowns
--   underdetermined, [N] §6); the normal equations' (the mass matrix's) printed;
--   at 0 degrees the x-components of grad(colour) at each pair of points
--   with identical y, equal to round-off ([T] eq 7.17, closed form); the largest
--   normal error at each rotation (printed; [T] gives no numbers) growing as the
--   pairs line up
-- assumed: [T] gives neither the arc nor the rotations. Here five points at 60,
--   75, 90, 105 and 120 degrees on the circle of radius 0.6 about (0.5, -0.1)
--   (an arc across the upper middle of the unit cell), turned about (0.5, 0.5);
--   the point of colour 0 at (0.3, 0.2), inside the arc's curve and off its axis
--   (a symmetric one would make every n_x zero at 0 degrees), turned with
--   it; one 4 x 4 system, the normal equations (lamina's method = "mass_matrix" per cell)
-- thumb: normals_mass_matrix_arc.png
local nu = require("normals_util")
local out = lamina.param("out", "out/normals_mass_matrix_arc")

local function turn(p, a)
  local c, s = math.cos(a), math.sin(a)
  local x, y = p[1] - 0.5, p[2] - 0.5
  return {0.5 + c * x - s * y, 0.5 + s * x + c * y}
end

local rotations = {45, 30, 15, 0}
local fig = lamina.figure{ width = 1000, height = 1000, panels = {2, 2},
  title = "[T] Figs 83-84: mass matrix normals to an arc turned in its cell" }
local report, worst = {}, {}
local pair_diff = 0
for i, rot in ipairs(rotations) do
  local a = math.rad(rot)
  local pts, ex = {}, {}
  for _, d in ipairs{60, 75, 90, 105, 120} do
    local t = math.rad(d)
    pts[#pts + 1] = turn({0.5 + 0.6 * math.cos(t), -0.1 + 0.6 * math.sin(t)}, a)
    ex[#ex + 1] = {math.cos(t + a), math.sin(t + a)}
  end
  local r = lamina.normals{ points = pts, box = {0, 0, 1, 1}, basis = "linear",
                            solver = "normal_equations", random_point = turn({0.3, 0.2}, a),
                            orient = turn({0.5, -0.1}, a) }
  worst[i] = math.deg(nu.max_angle(r.normals, ex))
  local label = i <= 2 and string.format("Fig 83 (%s)", i == 1 and "top" or "bottom")
                        or string.format("Fig 84 (%s)", i == 3 and "top" or "bottom")
  fig:panel{ index = i, window = {-0.05, -0.05, 1.05, 1.05},
             title = string.format("%s: turned %d deg", label, rot),
             caption = string.format("largest error %.1f deg", worst[i]) }
  fig:normals{ result = r, points = pts, exact = ex, length = 0.15 }
  if rot == 0 then
    -- the pairs at identical y: (1, 5) and (2, 4); the bilinear colour's
    -- x-derivative at height y is c(1, y) - c(0, y) exactly
    local function gx(y) return r.phi_at(1, y) - r.phi_at(0, y) end
    local function gy(x) return r.phi_at(x, 1) - r.phi_at(x, 0) end
    local scale, words = 0, {}
    for _, pr in ipairs{{1, 5}, {2, 4}} do
      local g1, g2 = gx(pts[pr[1]][2]), gx(pts[pr[2]][2])
      scale = math.max(scale, math.sqrt(g1 * g1 + gy(pts[pr[1]][1]) ^ 2))
      pair_diff = math.max(pair_diff, math.abs(g1 - g2))
      print(string.format("pair %d-%d at y = %.4f: d colour/dx %.12g and %.12g; computed n_x %.4f, %.4f; "
        .. "exact n_x %.4f, %.4f", pr[1], pr[2], pts[pr[1]][2], g1, g2, r.normals[pr[1]][1],
        r.normals[pr[2]][1], ex[pr[1]][1], ex[pr[2]][1]))
      words[#words + 1] = string.format("p%d, p%d: %.3f, %.3f", pr[1], pr[2], g1, g2)
      for _, k in ipairs(pr) do
        fig:text{ text = string.format("p%d", k), at = {pts[k][1], pts[k][2] - 0.06}, align = "center" }
      end
    end
    fig:caption{ text = "identical y; d colour/dx " .. table.concat(words, "; ") }
    pair_diff = pair_diff / scale
  end
  report[string.format("max_error_turned_%d", rot)] = { worst[i], unit = "deg ([T] gives none)" }
end
fig:write(out .. "/normals_mass_matrix_arc.png")

-- [T] Fig 85: Fig 84 (bottom)'s points with the quadratic functions (§7.7)
local pts85, ex85 = {}, {}
for _, d in ipairs{60, 75, 90, 105, 120} do
  local t = math.rad(d)
  pts85[#pts85 + 1] = {0.5 + 0.6 * math.cos(t), -0.1 + 0.6 * math.sin(t)}
  ex85[#ex85 + 1] = {math.cos(t), math.sin(t)}
end
local function quad(solver)
  return lamina.normals{ points = pts85, box = {0, 0, 1, 1}, basis = "quadratic", solver = solver,
                         random_point = {0.3, 0.2}, orient = {0.5, -0.1} }
end
local rq, rn = quad("qr"), quad("normal_equations")
local wq, wn = math.deg(nu.max_angle(rq.normals, ex85)), math.deg(nu.max_angle(rn.normals, ex85))
local f85 = lamina.figure{ width = 560, height = 600, panels = {1, 1},
  title = "[T] Fig 85: the arc of Fig 84 (bottom), quadratic functions" }
f85:panel{ index = 1, window = {-0.05, -0.05, 1.05, 1.05},
           caption = string.format("largest error %.2f deg (QR; normal equations %.1f deg)", wq, wn) }
f85:normals{ result = rq, points = pts85, exact = ex85, length = 0.15 }
f85:write(out .. "/fig85.png")
print(string.format("Fig 85: quadratic, largest error %.3f deg by QR (rank %d of %d), %.3f deg by the normal equations",
                    wq, rq.rank, rq.unknowns, wn))
report.fig85_max_error = { wq, ref = 0, tol = 1, unit = "deg (QR; [T]: on top of the theoretical ones; tol ours)" }
report.fig85_max_error_normal_equations = { wn, unit = "deg (the mass matrix solved by the normal equations)" }
print(string.format("largest errors: %s deg", table.concat((function()
  local t = {}
  for i, w in ipairs(worst) do t[i] = string.format("%d: %.2f", rotations[i], w) end
  return t end)(), ", ")))
report.pair_grad_x_difference = { pair_diff, ref = 0, tol = 1e-12,
                                  unit = "of |grad colour| ([T] eq 7.17: one n_x at one y)" }
report.error_grows = { worst[#worst] > worst[1] and 1 or 0, ref = 1, tol = 0,
                       unit = "(1: the upright arc's error above the 45-degree one's)" }
lamina.report(report)
