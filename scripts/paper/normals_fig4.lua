-- title: Curved membranes in one element, linear basis: a bilinear curve and a circle (normals paper Fig 4, Table III)
-- source: normals paper Fig 4 (a-b) and Table III ([N] §4, "Two Dimensions")
-- look: (a) the bold phi = 1 contour runs exactly through the three points of the curve and the
--       computed normals cover the dashed exact ones; (b) on the circle the phi = 1 contour is a
--       hyperbola-like curve close to the arc and the computed normals (solid) lean away from the
--       exact ones (dashed), most at the ends of the arc.
-- checks: (a) exact to round-off; (b) max error (paper 7 degrees, within half a degree, the
--         printed precision); Table III: max and rms error for 3, 4, 8, 16, 32 points with the
--         random point fixed (paper 0.1211 ... 0.1308 rad max, rms 0.0571 -> 0.0092), each within
--         9 %: [N] calls the maximum "unaffected" by the number of points while its own maxima
--         differ by +-9 % of their mean, a difference it counts as none; the rms as [N]'s
--         numbers fit (below) checked, the usual rms printed beside it; cond(T) over 100 random
--         points with 3 points (paper min 1.8e+01, max 4.1e+06, median 1.1e+02). Our maxima are
--         about 40 % above [N]'s: the paper places its points and random point where it does not
--         say (ours: both ends of the quarter arc), so the misses show as x.
-- assumed: (a) the printed curve xy + 0.1x + 0.3 = 0 never enters the unit square [0,1]^2 (x > 0
--          gives y < -0.1); it runs through [-1, 0] x [0, 1], the element used here (the same
--          curve mirrored is xy + 0.1x - 0.3 = 0 in [0,1]^2). Its three points are at x = -1 + (k +
--          1/2)/3 of the part inside. (b) n points evenly spaced in angle on the quarter of the
--          circle inside the unit element, both ends included. The paper's "rms" cannot be a root
--          mean square over the points: with 3 points it is 0.0571 < 0.1211 / sqrt(3); its
--          numbers fit sqrt(sum e^2) / n, printed here beside the usual rms.
local nu = require("normals_util")
local angle, errors = nu.angle, nu.errors
local out = lamina.param("out", "out/normals_fig4")
local seed = lamina.param("seed", 1)

-- (a) the bilinear curve xy + 0.1x + 0.3 = 0: y = -0.1 - 0.3/x, in [-1, 0] x [0, 1]
local function bilinear_points(n)
  local xe = -0.3 / 1.1                 -- where y = 1
  local pts, ex = {}, {}
  for k = 0, n - 1 do
    local x = -1 + (k + 0.5) / n * (xe + 1)
    local y = -0.1 - 0.3 / x
    local gx, gy = y + 0.1, x           -- grad(xy + 0.1x + 0.3)
    local l = math.sqrt(gx * gx + gy * gy)
    pts[#pts + 1], ex[#ex + 1] = {x, y}, {-gx / l, -gy / l}
  end
  return pts, ex
end

-- (b) the circle x^2 + y^2 = 0.8^2, quarter inside [0,1]^2, ends included
local function circle_points(n)
  local pts, ex = {}, {}
  for k = 0, n - 1 do
    local t = 0.5 * math.pi * k / (n - 1)
    pts[#pts + 1], ex[#ex + 1] = {0.8 * math.cos(t), 0.8 * math.sin(t)}, {math.cos(t), math.sin(t)}
  end
  return pts, ex
end

local fig = lamina.figure{width = 900, height = 520, panels = {2, 1},
  title = "Normals paper Fig 4: three points on curves, linear basis"}

local pa, ea = bilinear_points(3)
local ra = lamina.normals{points = pa, box = {-1, 0, 0, 1}, seed = seed, orient = {0, 0}}
local ma = errors(ra.normals, ea)
fig:panel{index = 1, window = {-1.1, -0.1, 0.1, 1.1}, title = "(a) xy + 0.1x + 0.3 = 0 in [-1,0] x [0,1]",
          caption = string.format("max error %.1e rad (paper: exact)", ma)}
fig:normals{result = ra, points = pa, exact = ea}
print(string.format("Fig 4(a): max error %.2e rad, cond(T) %.3g (paper: exact)", ma, ra.cond))

local pb, eb = circle_points(3)
local rb = lamina.normals{points = pb, box = {0, 0, 1, 1}, seed = seed, orient = {0, 0}}
local mb = errors(rb.normals, eb)
fig:panel{index = 2, window = {-0.1, -0.1, 1.1, 1.1}, title = "(b) x^2 + y^2 = 0.8^2",
          caption = string.format("max error %.1f deg (paper 7 deg), cond(T) %.2g", math.deg(mb),
                                  rb.cond)}
fig:polyline{points = (function() local c = {} for k = 0, 60 do local t = math.pi / 120 * k
  c[#c + 1] = {0.8 * math.cos(t), 0.8 * math.sin(t)} end return c end)(), dashed = true}
fig:normals{result = rb, points = pb, exact = eb}
fig:write(out .. "/normals_fig4.png")
print(string.format("Fig 4(b): max error %.2f deg (paper 7 deg)", math.deg(mb)))

-- cond(T) over 100 random points, 3 points on the circle
local conds = {}
for t = 1, 100 do
  conds[t] = lamina.normals{points = pb, box = {0, 0, 1, 1}, seed = t}.cond
end
table.sort(conds)
print(string.format("Fig 4(b), 100 random points: cond(T) min %.2g max %.2g median %.2g "
  .. "(paper 1.8e+01, 4.1e+06, 1.1e+02)", conds[1], conds[100], 0.5 * (conds[50] + conds[51])))

-- Table III: more points, the random point held where it fell in (b)
local paper = { [3] = {0.1211, 0.0571}, [4] = {0.1091, 0.0434}, [8] = {0.1177, 0.0231},
                [16] = {0.1261, 0.0141}, [32] = {0.1308, 0.0092} }
print("Table III (radians): points   max    rms   sqrt(sum e^2)/n | paper: max    rms")
local rms_paper_style = {}
for _, n in ipairs({3, 4, 8, 16, 32}) do
  local p, e = circle_points(n)
  local r = lamina.normals{points = p, box = {0, 0, 1, 1}, random_point = rb.random_point}
  local m, rms, alt = errors(r.normals, e)
  rms_paper_style[#rms_paper_style + 1] = alt
  print(string.format("                %2d   %.4f %.4f %.4f          | %.4f %.4f", n, m, rms, alt,
                      paper[n][1], paper[n][2]))
  if lamina.report then
    -- tol: [N] §4 calls the maximum "unaffected" by the number of points
    -- while its own maxima span 0.1091-0.1308, +-9 % of their mean: a
    -- difference the paper counts as none (issue 32: was +-0.1 / +-0.03)
    lamina.report{ ["table3_max_" .. n] = {m, paper = paper[n][1], tol = 0.09 * paper[n][1],
                     unit = "rad (tol 9 %: the spread of [N]'s own maxima it calls unaffected)"},
                   ["table3_rms_" .. n] = {alt, paper = paper[n][2], tol = 0.09 * paper[n][2],
                     unit = "rad, sqrt(sum e^2) / n as [N]'s numbers fit (tol 9 %, as the max)"},
                   ["table3_rms_usual_" .. n] = {rms, unit = "rad, sqrt(sum e^2 / n): the usual rms"} }
  end
end
if lamina.report then
  lamina.report{ fig4a_max_error = {ma, paper = 0, unit = "rad", tol = 1e-10},
                 -- "7" printed to the degree (Table III's 0.1211 rad = 6.94 deg is it): +-0.5
                 fig4b_max_error = {math.deg(mb), paper = 7, tol = 0.5,
                                    unit = "deg (tol: half the printed degree)"} }
end
