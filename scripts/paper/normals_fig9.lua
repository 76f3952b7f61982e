-- title: The quadratic basis on the arc of Fig 7: normal equations vs QR, underdetermined vs 8 points (normals paper Fig 9)
-- source: normals paper Fig 9 (a-d) and §6: "The calculations for Figure 9 are done by solving the
--         normal equations. Using a QR-decomposition ... the result for Figure 9(b) is a maximum
--         error of less than one degree."
-- look: top row, the arcs of Fig 7 with the 9 x 9 quadratic construction, which is underdetermined
--       (5 points + 1 random point = 6 rows): by the normal equations (left of each pair) the
--       contours wander and some normals are visibly off; by QR's minimum-norm solution (right)
--       the phi = 1 contour is close to the circle. Bottom row: 8 points, 9 rows for 9 unknowns,
--       the contour is the circle itself and the normals are exact.
-- checks: max error of (a), (b) by the normal equations (paper 3 and 19 degrees) and by QR (paper
--         < 1 degree for (b)); medians over 100 random points of both (QR should win); (c), (d)
--         exact (paper: zero error).
-- assumed: (a), (b) as normals_fig7.lua (5 points on the quarters 180..270 and 225..315 deg);
--          (c), (d) 8 points 11.25 deg apart from 180 deg and from 225 deg. Eight points placed
--          symmetrically about a multiple of 45 deg (e.g. evenly over 180..270 with both ends)
--          make the 9 x 9 system exactly singular - a biquadratic restricted to the circle is a
--          trigonometric polynomial without the sin(4 theta) term - so the paper's 8 points were
--          not symmetric; the symmetric case is printed too (rank 8, minimum-norm solution).
local nu = require("normals_util")
local max_angle, median, spaced = nu.max_angle, nu.median, nu.spaced
local out = lamina.param("out", "out/normals_fig9")
local seed = lamina.param("seed", 1)

local function arc_points(angles)
  local pts, ex = {}, {}
  for k, a in ipairs(angles) do
    local t = math.rad(a)
    pts[k] = {0.5 + 0.3 * math.cos(t), 0.5 + 0.3 * math.sin(t)}
    ex[k] = {math.cos(t), math.sin(t)}
  end
  return pts, ex
end

local function solve(pts, solver, s)
  return lamina.normals{points = pts, box = {0, 0, 1, 1}, basis = "quadratic", solver = solver,
                        seed = s, orient = {0.5, 0.5}}
end

local fig = lamina.figure{width = 1200, height = 860, panels = {3, 2},
  title = "Normals paper Fig 9: quadratic (9 x 9) construction on the arc of Fig 7"}
local cases = {
  {angles = spaced(180, 22.5, 5), tag = "a", paper_ne = 3},
  {angles = spaced(225, 22.5, 5), tag = "b", paper_ne = 19, paper_qr = "< 1"},
}
local medians = {}
for _, c in ipairs(cases) do
  local pts, ex = arc_points(c.angles)
  for _, solver in ipairs({"normal_equations", "qr"}) do
    local r = solve(pts, solver, seed)
    local m = math.deg(max_angle(r.normals, ex))
    local all = {}
    for t = 1, 100 do all[t] = math.deg(max_angle(solve(pts, solver, t).normals, ex)) end
    local med = median(all)
    medians[c.tag .. solver] = med
    local paper = solver == "qr" and (c.paper_qr and c.paper_qr .. " deg" or "not given")
                  or c.paper_ne .. " deg"
    -- panels: row 1 is (a), row 2 is (b); normal equations, then QR
    local idx = (c.tag == "a" and 0 or 3) + (solver == "qr" and 2 or 1)
    fig:panel{index = idx, window = {0, 0, 1, 1},
              title = string.format("(%s) 5 points, %s", c.tag,
                solver == "qr" and "QR (minimum norm)" or "normal equations"),
              caption = string.format("max %.1f deg (paper %s), rank %d of %d; "
                .. "median of 100: %.1f deg", m, paper, r.rank, r.unknowns, med)}
    fig:polyline{points = nu.circle(0.5, 0.5, 0.3, 72), dashed = true}
    fig:normals{result = r, points = pts, exact = ex, length = 0.15}
    print(string.format("Fig 9(%s) %-16s max error %6.2f deg (paper %s), rank %d of %d; "
      .. "over 100 random points median %.2f deg", c.tag, solver, m, paper, r.rank, r.unknowns, med))
    if lamina.report then
      lamina.report{ [string.format("fig9%s_%s_median", c.tag, solver)] = {med, unit = "deg"} }
    end
  end
end

-- (c), (d): 8 points, the square 9 x 9 system
local worst8 = 0
for i, c in ipairs({{a0 = 180, tag = "c", idx = 3}, {a0 = 225, tag = "d", idx = 6}}) do
  local pts, ex = arc_points(spaced(c.a0, 11.25, 8))
  local r = solve(pts, "qr", seed)
  local m = max_angle(r.normals, ex)
  local w = 0
  for t = 1, 100 do w = math.max(w, max_angle(solve(pts, "qr", t).normals, ex)) end
  worst8 = math.max(worst8, w)
  fig:panel{index = c.idx, window = {0, 0, 1, 1},
            title = string.format("(%s) 8 points from %d deg, QR", c.tag, c.a0),
            caption = string.format("max error %.1e rad (paper 0), cond(T) %.2g", m, r.cond)}
  fig:polyline{points = nu.circle(0.5, 0.5, 0.3, 72), dashed = true}
  fig:normals{result = r, points = pts, exact = ex, length = 0.15}
  print(string.format("Fig 9(%s) 8 points: max error %.2e rad (paper 0), worst of 100 random "
    .. "points %.2e rad, cond(T) %.3g", c.tag, m, w, r.cond))
  local ne = solve(pts, "normal_equations", seed)
  print(string.format("          the same by the normal equations: %.2e rad",
                      max_angle(ne.normals, ex)))
end
fig:write(out .. "/normals_fig9.png")

-- the singular case: 8 points symmetric about 225 deg
local pts, ex = arc_points(spaced(180, 90 / 7, 8))
local r = solve(pts, "qr", seed)
print(string.format("8 points evenly over 180..270 deg (symmetric): rank %d of 9, cond(T) %.2g, "
  .. "minimum-norm max error %.3f deg", r.rank, r.cond, math.deg(max_angle(r.normals, ex))))

print(string.format("QR vs normal equations, medians over 100 random points: (a) %.2f vs %.2f deg, "
  .. "(b) %.2f vs %.2f deg", medians.aqr, medians.anormal_equations, medians.bqr,
  medians.bnormal_equations))
if lamina.report then
  lamina.report{ fig9cd_worst_error = {worst8, paper = 0, unit = "rad", tol = 1e-8} }
end
