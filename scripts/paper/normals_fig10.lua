-- title: A cubic curve with the quadratic basis: resolved (c = 2) and not resolved (c = 4) (normals paper Fig 10)
-- source: normals paper Fig 10 (a-b) ([N] §6): y = c x^2 (x - 1) + x + 0.5
-- look: (a) c = 2, radius of curvature >= about 0.5: the bold phi = 1 contour follows the curve
--       (dashed) and the normals are close to exact; (b) c = 4, radius of curvature down to about
--       0.2, smaller than the element: the contour cannot follow the wiggle and several normals
--       are far off.
-- checks: max angle error, paper (a) about 1 degree, (b) 32 degrees with an rms of about 5
--         degrees (the paper's rms is sqrt(sum e^2)/n, see normals_fig4.lua; both printed),
--         each within half a degree (the printed precision: [N] states no agreement; it was
--         1 +- 1 and 32 +- 16); medians over 100 random points.
-- assumed: the curve runs from (0, 0.5) to (1, 1.5), corner to corner of the element
--          [0, 1] x [0.5, 1.5], which is taken as the element (in [0,1]^2 it would leave through
--          the top at x = 0.77 or 0.88); n = 10 points evenly spaced in x, ends included.
local nu = require("normals_util")
local median = nu.median
local out = lamina.param("out", "out/normals_fig10")
local seed = lamina.param("seed", 1)
local npts = lamina.param("points", 10)

local function cubic_points(c, n)
  local pts, ex = {}, {}
  for k = 0, n - 1 do
    local x = k / (n - 1)
    local d = c * (3 * x * x - 2 * x) + 1          -- dy/dx
    local l = math.sqrt(1 + d * d)
    pts[#pts + 1] = {x, c * x * x * (x - 1) + x + 0.5}
    ex[#ex + 1] = {-d / l, 1 / l}
  end
  return pts, ex
end

local function errors(ns, ex)
  local m, s2 = 0, 0
  for k = 1, #ns do
    local c = math.abs(ns[k][1] * ex[k][1] + ns[k][2] * ex[k][2])
    local s = math.abs(ns[k][1] * ex[k][2] - ns[k][2] * ex[k][1])
    local a = math.atan(s, c)
    m, s2 = math.max(m, a), s2 + a * a
  end
  return math.deg(m), math.deg(math.sqrt(s2 / #ns)), math.deg(math.sqrt(s2) / #ns)
end

local box = {0, 0.5, 1, 1.5}
local fig = lamina.figure{width = 900, height = 520, panels = {2, 1},
  title = "Normals paper Fig 10: y = c x^2 (x - 1) + x + 0.5, quadratic basis"}
for i, c in ipairs({{c = 2, paper = "1", tag = "a"}, {c = 4, paper = "32, rms 5", tag = "b"}}) do
  local pts, ex = cubic_points(c.c, npts)
  local curve = cubic_points(c.c, 101)
  -- orient: away from a far point down-right, i.e. up-left like the exact normals
  local r = lamina.normals{points = pts, box = box, basis = "quadratic", seed = seed,
                           orient = {11, -9.5}}
  local m, rms, alt = errors(r.normals, ex)
  local all = {}
  for t = 1, 100 do
    all[t] = errors(lamina.normals{points = pts, box = box, basis = "quadratic", seed = t}.normals, ex)
  end
  local med = median(all)
  fig:panel{index = i, window = {-0.12, 0.38, 1.12, 1.62}, title = string.format("(%s) c = %d, %d points", c.tag, c.c, npts),
            caption = string.format("max %.1f deg, rms %.1f, sqrt(sum e^2)/n %.1f (paper %s deg)",
                                    m, rms, alt, c.paper)}
  fig:caption{text = string.format("median of the max over 100 random points: %.1f deg", med)}
  fig:polyline{points = curve, dashed = true}
  fig:normals{result = r, points = pts, exact = ex, length = 0.15}
  print(string.format("Fig 10(%s) c = %d: max %.2f deg, rms %.2f deg, sqrt(sum e^2)/n %.2f deg "
    .. "(paper: %s deg); median max over 100 random points %.2f deg", c.tag, c.c, m, rms, alt,
    c.paper, med))
  if lamina.report then
    -- [N] prints whole degrees ("about 1", "32", "rms of about 5") and no
    -- agreement: half a degree, its precision (issue 32: was 1 +- 1, 32 +- 16)
    local rep = { ["fig10" .. c.tag .. "_max_error"] = {m, paper = c.c == 2 and 1 or 32, tol = 0.5,
                                                        unit = "deg (tol: half the printed degree)"},
                  ["fig10" .. c.tag .. "_median_max_error"] = {med, unit = "deg"} }
    if c.c == 4 then
      rep.fig10b_rms_paper_style = {alt, paper = 5, tol = 0.5,
        unit = "deg, sqrt(sum e^2) / n as [N]'s Table III fits ([N]: 'about 5'; tol: half the printed degree)"}
      rep.fig10b_rms_usual = {rms, unit = "deg, sqrt(sum e^2 / n): the usual rms"}
    end
    lamina.report(rep)
  end
end
fig:write(out .. "/normals_fig10.png")
